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
    float3 _871 = fast::normalize(in.v_normal);
    float3 _875 = fast::normalize(in.v_toEye);
    float _1006 = _871.y;
    float _1011 = _871.z;
    float _1016 = _871.x;
    float _1134 = fast::max(dot(_871, _875), 9.9999997473787516355514526367188e-05);
    float3 _1138 = reflect(-_875, _871);
    float4 _1173 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1134, params.facet_perceptualRoughness), level(0.0));
    float3 _1192 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1173.y) - 1.0));
    float4 _1234 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1134, params.facet_sheenRoughness), level(0.0));
    float _1247 = _1234.z;
    float _1249 = fma(-fast::max(params.facet_sheenColor[0], fast::max(params.facet_sheenColor[1], params.facet_sheenColor[2])), _1247, 1.0);
    float3 _1273 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1006)) + (frame.sh[2].xyz * _1011)) + (frame.sh[3].xyz * _1016)) + (((((frame.sh[4].xyz * (_1016 * _1006)) + (frame.sh[5].xyz * (_1006 * _1011))) + (frame.sh[6].xyz * fma(3.0 * _1011, _1011, -1.0))) + (frame.sh[7].xyz * (_1016 * _1011))) + (frame.sh[8].xyz * fma(_1016, _1016, -(_1006 * _1006)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1138, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1173.xxx, _1173.yyy, float3(params.facet_f0)) * _1192)) * _1249;
    float3 _1410 = fast::normalize(_875 + frame.lightDirection.xyz);
    float _1343 = fast::clamp(dot(_871, frame.lightDirection.xyz), 0.0, 1.0);
    float _1347 = fast::clamp(dot(_871, _1410), 0.0, 1.0);
    float4 _1472 = float4(cross(_871, _1410), params.facet_alpha * _1347) * 64.0;
    float _1454 = (4096.0 * params.facet_alpha) / dot(_1472, _1472);
    float _1483 = params.facet_alpha * params.facet_alpha;
    float _1489 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1516 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1410), 0.0, 1.0);
    float _1519 = _1516 * _1516;
    float _1560 = 8192.0 * fma(-_1343, _1134, _1343 + _1134);
    float _1564 = 1.0 / (params.facet_sheenAlpha * _1560);
    float3 _1599 = fma(facet_environment.sample(facet_environmentSmplr, _1138, level(params.facet_sheenLod)).xyz, float3(params.facet_sheenColor) * _1247, _1273) + fast::min(fma(fma((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1519 * _1519) * _1516))) * (((_1454 * _1454) * 0.3183098733425140380859375) * (0.5 / fma(_1343, sqrt(fma(_1134 * _1134, _1489, _1483)), _1134 * sqrt(fma(_1343 * _1343, _1489, _1483))))), _1192, float3(params.facet_diffuseColor) * 0.3183098733425140380859375), (frame.lightColor.xyz * _1343) * _1249, (float3(params.facet_sheenColor) * ((((fma(_1564, _1560, 2.0) * pow(fast::max(fma(-_1347, _1347, 1.0), 0.0), 0.5 * (_1564 * _1560))) * 0.15915493667125701904296875) * (_1343 * (_1564 * (2048.0 * params.facet_sheenAlpha)))) * _1234.w)) * frame.lightColor.xyz), float3(65504.0));
    out.fragColor = float4(_1599, 1.0);
    return out;
}

