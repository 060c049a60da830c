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
    float _1282 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1239 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1140, _1282), level(0.0));
    float3 _1289 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1252 = _1239.z;
    float _1254 = fma(-fast::max(_1289.x, fast::max(_1289.y, _1289.z)), _1252, 1.0);
    float _1298 = _1282 * _1282;
    float3 _1275 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1012)) + (frame.sh[2].xyz * _1017)) + (frame.sh[3].xyz * _1022)) + (((((frame.sh[4].xyz * (_1022 * _1012)) + (frame.sh[5].xyz * (_1012 * _1017))) + (frame.sh[6].xyz * fma(3.0 * _1017, _1017, -1.0))) + (frame.sh[7].xyz * (_1022 * _1017))) + (frame.sh[8].xyz * fma(_1022, _1022, -(_1012 * _1012)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1144, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1179.xxx, _1179.yyy, float3(params.facet_f0)) * _1198)) * _1254;
    float3 _1434 = fast::normalize(_882 + frame.lightDirection.xyz);
    float _1367 = fast::clamp(dot(_878, frame.lightDirection.xyz), 0.0, 1.0);
    float _1371 = fast::clamp(dot(_878, _1434), 0.0, 1.0);
    float3 _1492 = cross(_878, _1434) * 64.0;
    float _1496 = _1371 * (64.0 * params.facet_alpha);
    float _1479 = (4096.0 * params.facet_alpha) / fma(_1496, _1496, dot(_1492, _1492));
    float _1511 = params.facet_alpha * params.facet_alpha;
    float _1517 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1544 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1434), 0.0, 1.0);
    float _1547 = _1544 * _1544;
    float _1588 = 8192.0 * fma(-_1367, _1140, _1367 + _1140);
    float _1592 = 1.0 / (_1298 * _1588);
    float3 _1627 = fma(facet_environment.sample(facet_environmentSmplr, _1144, level(_1282 * 4.0)).xyz, _1289 * _1252, _1275) + fast::min(fma(fma((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1547 * _1547) * _1544))) * (((_1479 * _1479) * 0.3183098733425140380859375) * (0.5 / fma(_1367, sqrt(fma(_1140 * _1140, _1517, _1511)), _1140 * sqrt(fma(_1367 * _1367, _1517, _1511))))), _1198, float3(params.facet_diffuseColor) * 0.3183098733425140380859375), (frame.lightColor.xyz * _1367) * _1254, (_1289 * ((((fma(_1592, _1588, 2.0) * pow(fast::max(fma(-_1371, _1371, 1.0), 0.0), 0.5 * (_1592 * _1588))) * 0.15915493667125701904296875) * (_1367 * (_1592 * (2048.0 * _1298)))) * _1239.w)) * frame.lightColor.xyz), float3(65504.0));
    out.fragColor = float4(_1627, 1.0);
    return out;
}

