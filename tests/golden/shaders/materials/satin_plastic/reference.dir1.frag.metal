#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    packed_float3 facet_f0;
    float facet_alpha;
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    char _m11_pad[4];
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
    float facet_sheenRoughness;
    float facet_sheenAlpha;
};

struct PunctualLightData
{
    float4 positionFalloff;
    float4 colorIntensity;
    float4 direction;
    float4 spotScaleOffset;
};

struct FrameUniforms
{
    float4x4 viewProjection;
    float4 cameraPosition;
    float4 lightDirection;
    float4 lightColor;
    float4 ambient;
    PunctualLightData punctualLights[4];
    float4 sh[9];
};

struct main0_out
{
    float4 fragColor [[color(0)]];
};

struct main0_in
{
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    float3 _858 = fast::normalize(in.v_normal);
    float3 _862 = fast::normalize(in.v_toEye);
    float _993 = _858.y;
    float _998 = _858.z;
    float _1003 = _858.x;
    float _1119 = fast::max(dot(_858, _862), 9.9999997473787516355514526367188e-05);
    float3 _1123 = reflect(-_862, _858);
    float4 _1161 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1119, params.facet_perceptualRoughness), level(0.0));
    float3 _1180 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1161.y) - 1.0));
    float4 _1211 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1119, params.facet_sheenRoughness), level(0.0));
    float _1224 = _1211.z;
    float _1226 = fma(-fast::max(params.facet_sheenColor[0], fast::max(params.facet_sheenColor[1], params.facet_sheenColor[2])), _1224, 1.0);
    float3 _1250 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _993)) + (frame.sh[2].xyz * _998)) + (frame.sh[3].xyz * _1003)) + (((((frame.sh[4].xyz * (_1003 * _993)) + (frame.sh[5].xyz * (_993 * _998))) + (frame.sh[6].xyz * fma(3.0 * _998, _998, -1.0))) + (frame.sh[7].xyz * (_1003 * _998))) + (frame.sh[8].xyz * fma(_1003, _1003, -(_993 * _993)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1123, level(params.facet_environmentLod)).xyz * (mix(_1161.xxx, _1161.yyy, float3(params.facet_f0)) * _1180)) * _1226;
    float _1317 = fast::clamp(dot(_858, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1387 = fast::normalize(_862 + frame.lightDirection.xyz);
    float _1324 = fast::clamp(dot(_858, _1387), 0.0, 1.0);
    float4 _1449 = float4(cross(_858, _1387), params.facet_alpha * _1324) * 64.0;
    float _1431 = (4096.0 * params.facet_alpha) / dot(_1449, _1449);
    float _1460 = params.facet_alpha * params.facet_alpha;
    float _1466 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1493 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1387), 0.0, 1.0);
    float _1496 = _1493 * _1493;
    float _1537 = 8192.0 * fma(-_1317, _1119, _1317 + _1119);
    float _1541 = 1.0 / (params.facet_sheenAlpha * _1537);
    float3 _1576 = fma(facet_environment.sample(facet_environmentSmplr, _1123, level(params.facet_sheenLod)).xyz, float3(params.facet_sheenColor) * _1224, _1250) + fast::min(fma(fma((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1496 * _1496) * _1493))) * (((_1431 * _1431) * 0.3183098733425140380859375) * (0.5 / fma(_1317, sqrt(fma(_1119 * _1119, _1466, _1460)), _1119 * sqrt(fma(_1317 * _1317, _1466, _1460))))), _1180, float3(params.facet_diffuseColor) * 0.3183098733425140380859375), (frame.lightColor.xyz * _1317) * _1226, (float3(params.facet_sheenColor) * ((((fma(_1541, _1537, 2.0) * pow(fast::max(fma(-_1324, _1324, 1.0), 0.0), 0.5 * (_1541 * _1537))) * 0.15915493667125701904296875) * (_1317 * (_1541 * (2048.0 * params.facet_sheenAlpha)))) * _1211.w)) * frame.lightColor.xyz), float3(65504.0));
    out.fragColor = float4(_1576, 1.0);
    return out;
}

