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
    float3 _878 = fast::normalize(in.v_normal);
    float3 _882 = fast::normalize(in.v_toEye);
    float _1012 = _878.y;
    float _1017 = _878.z;
    float _1022 = _878.x;
    float _1140 = fast::max(dot(_878, _882), 9.9999997473787516355514526367188e-05);
    float3 _1144 = reflect(-_882, _878);
    float4 _1179 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1140, params.facet_perceptualRoughness), level(0.0));
    float3 _1198 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1179.y) - 1.0));
    float _1285 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1242 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1140, _1285), level(0.0));
    float3 _1292 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1255 = _1242.z;
    float _1257 = fma(-fast::max(_1292.x, fast::max(_1292.y, _1292.z)), _1255, 1.0);
    float _1301 = _1285 * _1285;
    float3 _1278 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1012)) + (frame.sh[2].xyz * _1017)) + (frame.sh[3].xyz * _1022)) + (((((frame.sh[4].xyz * (_1022 * _1012)) + (frame.sh[5].xyz * (_1012 * _1017))) + (frame.sh[6].xyz * fma(3.0 * _1017, _1017, -1.0))) + (frame.sh[7].xyz * (_1022 * _1017))) + (frame.sh[8].xyz * fma(_1022, _1022, -(_1012 * _1012)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1144, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1179.xxx, _1179.yyy, float3(params.facet_f0)) * _1198)) * _1257;
    float3 _1440 = fast::normalize(_882 + frame.lightDirection.xyz);
    float _1373 = fast::clamp(dot(_878, frame.lightDirection.xyz), 0.0, 1.0);
    float _1377 = fast::clamp(dot(_878, _1440), 0.0, 1.0);
    float4 _1502 = float4(cross(_878, _1440), params.facet_alpha * _1377) * 64.0;
    float _1484 = (4096.0 * params.facet_alpha) / dot(_1502, _1502);
    float _1513 = params.facet_alpha * params.facet_alpha;
    float _1519 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1546 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1440), 0.0, 1.0);
    float _1549 = _1546 * _1546;
    float _1590 = 8192.0 * fma(-_1373, _1140, _1373 + _1140);
    float _1594 = 1.0 / (_1301 * _1590);
    float3 _1629 = fma(facet_environment.sample(facet_environmentSmplr, _1144, level(_1285 * (4.0 * (2.0 - _1285)))).xyz, _1292 * _1255, _1278) + fast::min(fma(fma((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1549 * _1549) * _1546))) * (((_1484 * _1484) * 0.3183098733425140380859375) * (0.5 / fma(_1373, sqrt(fma(_1140 * _1140, _1519, _1513)), _1140 * sqrt(fma(_1373 * _1373, _1519, _1513))))), _1198, float3(params.facet_diffuseColor) * 0.3183098733425140380859375), (frame.lightColor.xyz * _1373) * _1257, (_1292 * ((((fma(_1594, _1590, 2.0) * pow(fast::max(fma(-_1377, _1377, 1.0), 0.0), 0.5 * (_1594 * _1590))) * 0.15915493667125701904296875) * (_1373 * (_1594 * (2048.0 * _1301)))) * _1242.w)) * frame.lightColor.xyz), float3(65504.0));
    out.fragColor = float4(_1629, 1.0);
    return out;
}

