#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float facet_perceptualRoughness;
    char _m3_pad[12];
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
    float3 v_worldPosition [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _787 = normalize(half3(in.v_normal));
    float3 _793 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1081 = max(dot(_787, half3(_793)), half(9.9999997473787516355514526367188e-05));
    float4 _1120 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1081, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1139 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1120).y) - half(1.0)));
    float4 _1146 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_793), _787)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1262 = fast::normalize(_793 + frame.lightDirection.xyz);
    half _1206 = clamp(dot(_787, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1303 = half(4096.0) * half(params.facet_alpha);
    half3 _1323 = cross(_787, half3(_1262)) * half(64.0);
    half _1326 = half(64.0) * half(params.facet_alpha);
    half _1327 = clamp(dot(_787, half3(_1262)), half(0.0), half(1.0)) * _1326;
    half _1309 = _1303 / fma(_1327, _1327, dot(_1323, _1323));
    half _1342 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1348 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1352 = sqrt(fma(_1081 * _1081, _1348, _1342));
    half _1376 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1262)), half(0.0), half(1.0));
    half _1379 = _1376 * _1376;
    half3 _1387 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1445 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1448 = dot(_1445, _1445);
    float3 _1453 = _1445 * rsqrt(fast::max(_1448, 9.9999999392252902907785028219223e-09));
    float _1457 = _1448 * float(frame.punctualLights[0].positionFalloff.w);
    float _1462 = fast::clamp(fma(-_1457, _1457, 1.0), 0.0, 1.0);
    float _1481 = fast::clamp(fma(dot(-_1453, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1600 = fast::normalize(_793 + _1453);
    half _1544 = clamp(dot(_787, half3(_1453)), half(0.0), half(1.0));
    half3 _1661 = cross(_787, half3(_1600)) * half(64.0);
    half _1665 = clamp(dot(_787, half3(_1600)), half(0.0), half(1.0)) * _1326;
    half _1647 = _1303 / fma(_1665, _1665, dot(_1661, _1661));
    half _1714 = half(1.0) - clamp(dot(half3(_1453), half3(_1600)), half(0.0), half(1.0));
    half _1717 = _1714 * _1714;
    float3 _1783 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1786 = dot(_1783, _1783);
    float3 _1791 = _1783 * rsqrt(fast::max(_1786, 9.9999999392252902907785028219223e-09));
    float _1795 = _1786 * float(frame.punctualLights[1].positionFalloff.w);
    float _1800 = fast::clamp(fma(-_1795, _1795, 1.0), 0.0, 1.0);
    float _1819 = fast::clamp(fma(dot(-_1791, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1938 = fast::normalize(_793 + _1791);
    half _1882 = clamp(dot(_787, half3(_1791)), half(0.0), half(1.0));
    half3 _1999 = cross(_787, half3(_1938)) * half(64.0);
    half _2003 = clamp(dot(_787, half3(_1938)), half(0.0), half(1.0)) * _1326;
    half _1985 = _1303 / fma(_2003, _2003, dot(_1999, _1999));
    half _2052 = half(1.0) - clamp(dot(half3(_1791), half3(_1938)), half(0.0), half(1.0));
    half _2055 = _2052 * _2052;
    half3 _2085 = (fma(half4(_1146).xyz, mix(half4(_1120).xxx, half4(_1120).yyy, half3(float3(params.facet_f0))) * _1139, min((((half3(float3(params.facet_f0)) + (_1387 * ((_1379 * _1379) * _1376))) * min(min((_1309 * _1309) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1206, _1352, _1081 * sqrt(fma(_1206 * _1206, _1348, _1342))), half(65504.0)), half(65504.0))) * _1139) * (half4(frame.lightColor).xyz * _1206), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1387 * ((_1717 * _1717) * _1714))) * min(min((_1647 * _1647) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1544, _1352, _1081 * sqrt(fma(_1544 * _1544, _1348, _1342))), half(65504.0)), half(65504.0))) * _1139) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1462) * half(_1462)) / fast::max(_1448, 9.9999997473787516355514526367188e-05)) * half(_1481)) * half(_1481)), float3(65504.0))) * _1544), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1387 * ((_2055 * _2055) * _2052))) * min(min((_1985 * _1985) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1882, _1352, _1081 * sqrt(fma(_1882 * _1882, _1348, _1342))), half(65504.0)), half(65504.0))) * _1139) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1800) * half(_1800)) / fast::max(_1786, 9.9999997473787516355514526367188e-05)) * half(_1819)) * half(_1819)), float3(65504.0))) * _1882), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2085, half(1.0)));
    return out;
}

