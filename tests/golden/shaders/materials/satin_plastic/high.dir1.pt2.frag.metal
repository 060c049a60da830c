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
    float3 v_worldPosition [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _963 = normalize(half3(in.v_normal));
    float3 _969 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1136 = _963.y;
    half _1141 = _963.z;
    half _1146 = _963.x;
    half3 _1214 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1136)) + (half4(frame.sh[2]).xyz * _1141)) + (half4(frame.sh[3]).xyz * _1146)) + (((((half4(frame.sh[4]).xyz * (_1146 * _1136)) + (half4(frame.sh[5]).xyz * (_1136 * _1141))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1141, _1141, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1146 * _1141))) + (half4(frame.sh[8]).xyz * fma(_1146, _1146, half(-float(_1136 * _1136))))), half3(float3(0.0)));
    half _1264 = max(dot(_963, half3(_969)), half(9.9999997473787516355514526367188e-05));
    half3 _1268 = reflect(-half3(_969), _963);
    float4 _1303 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1264, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1322 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1303).y) - half(1.0)));
    float4 _1329 = facet_environment.sample(facet_environmentSmplr, float3(_1268), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1406 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1363 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1264, _1406)), level(0.0));
    half3 _1413 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2724 = half4(_1363);
    half _1376 = _2724.z;
    half _1378 = fma(half(-float(max(_1413.x, max(_1413.y, _1413.z)))), _1376, half(1.0));
    half _1422 = _1406 * _1406;
    half4 _2728 = half4(_1363);
    half _1383 = _2728.w;
    float4 _1434 = facet_environment.sample(facet_environmentSmplr, float3(_1268), level(_1406 * half(4.0)));
    half3 _1024 = half4(frame.lightColor).xyz;
    float3 _1559 = fast::normalize(_969 + frame.lightDirection.xyz);
    half _1491 = clamp(dot(_963, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1495 = clamp(dot(_963, half3(_1559)), half(0.0), half(1.0));
    half3 _1599 = cross(_963, half3(_1559));
    half _1602 = _1495 * half(params.facet_alpha);
    half _1611 = half(params.facet_alpha) / fma(_1602, _1602, dot(_1599, _1599));
    half _1625 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1631 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1635 = sqrt(fma(_1264 * _1264, _1631, _1625));
    half _1659 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1559)), half(0.0), half(1.0));
    half _1662 = _1659 * _1659;
    half3 _1670 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1703 = half(8192.0) * fma(half(-float(_1491)), _1264, _1491 + _1264);
    half _1707 = half(1.0) / (_1422 * _1703);
    half _1714 = half(2048.0) * _1422;
    half3 _1532 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    half3 _1540 = min(fma(fma((half3(float3(params.facet_f0)) + (_1670 * ((_1662 * _1662) * _1659))) * min(min((_1611 * _1611) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1491, _1635, _1264 * sqrt(fma(_1491 * _1491, _1631, _1625))), half(65504.0)), half(65504.0)), _1322, _1532), (_1024 * _1491) * _1378, (_1413 * ((((fma(_1707, _1703, half(2.0)) * pow(max(fma(half(-float(_1495)), _1495, half(1.0)), half(0.0)), half(0.5) * (_1707 * _1703))) * half(0.15915493667125701904296875)) * (_1491 * (_1707 * _1714))) * _1383)) * _1024), half3(float3(65504.0)));
    float3 _1778 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1781 = dot(_1778, _1778);
    float3 _1786 = _1778 * rsqrt(fast::max(_1781, 9.9999999392252902907785028219223e-09));
    float _1790 = _1781 * float(frame.punctualLights[0].positionFalloff.w);
    float _1795 = fast::clamp(fma(-_1790, _1790, 1.0), 0.0, 1.0);
    float _1814 = fast::clamp(fma(dot(-_1786, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1825 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1795) * half(_1795)) / fast::max(_1781, 9.9999997473787516355514526367188e-05)) * half(_1814)) * half(_1814)), float3(65504.0));
    float3 _1950 = fast::normalize(_969 + _1786);
    half _1882 = clamp(dot(_963, half3(_1786)), half(0.0), half(1.0));
    half _1886 = clamp(dot(_963, half3(_1950)), half(0.0), half(1.0));
    half3 _1990 = cross(_963, half3(_1950));
    half _1993 = _1886 * half(params.facet_alpha);
    half _2002 = half(params.facet_alpha) / fma(_1993, _1993, dot(_1990, _1990));
    half _2050 = half(1.0) - clamp(dot(half3(_1786), half3(_1950)), half(0.0), half(1.0));
    half _2053 = _2050 * _2050;
    half _2094 = half(8192.0) * fma(half(-float(_1882)), _1264, _1882 + _1264);
    half _2098 = half(1.0) / (_1422 * _2094);
    half3 _1931 = min(fma(fma((half3(float3(params.facet_f0)) + (_1670 * ((_2053 * _2053) * _2050))) * min(min((_2002 * _2002) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1882, _1635, _1264 * sqrt(fma(_1882 * _1882, _1631, _1625))), half(65504.0)), half(65504.0)), _1322, _1532), (half3(_1825) * _1882) * _1378, (_1413 * ((((fma(_2098, _2094, half(2.0)) * pow(max(fma(half(-float(_1886)), _1886, half(1.0)), half(0.0)), half(0.5) * (_2098 * _2094))) * half(0.15915493667125701904296875)) * (_1882 * (_2098 * _1714))) * _1383)) * half3(_1825)), half3(float3(65504.0)));
    float3 _2169 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2172 = dot(_2169, _2169);
    float3 _2177 = _2169 * rsqrt(fast::max(_2172, 9.9999999392252902907785028219223e-09));
    float _2181 = _2172 * float(frame.punctualLights[1].positionFalloff.w);
    float _2186 = fast::clamp(fma(-_2181, _2181, 1.0), 0.0, 1.0);
    float _2205 = fast::clamp(fma(dot(-_2177, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2216 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2186) * half(_2186)) / fast::max(_2172, 9.9999997473787516355514526367188e-05)) * half(_2205)) * half(_2205)), float3(65504.0));
    float3 _2341 = fast::normalize(_969 + _2177);
    half _2273 = clamp(dot(_963, half3(_2177)), half(0.0), half(1.0));
    half _2277 = clamp(dot(_963, half3(_2341)), half(0.0), half(1.0));
    half3 _2381 = cross(_963, half3(_2341));
    half _2384 = _2277 * half(params.facet_alpha);
    half _2393 = half(params.facet_alpha) / fma(_2384, _2384, dot(_2381, _2381));
    half _2441 = half(1.0) - clamp(dot(half3(_2177), half3(_2341)), half(0.0), half(1.0));
    half _2444 = _2441 * _2441;
    half _2485 = half(8192.0) * fma(half(-float(_2273)), _1264, _2273 + _1264);
    half _2489 = half(1.0) / (_1422 * _2485);
    half3 _2322 = min(fma(fma((half3(float3(params.facet_f0)) + (_1670 * ((_2444 * _2444) * _2441))) * min(min((_2393 * _2393) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2273, _1635, _1264 * sqrt(fma(_2273 * _2273, _1631, _1625))), half(65504.0)), half(65504.0)), _1322, _1532), (half3(_2216) * _2273) * _1378, (_1413 * ((((fma(_2489, _2485, half(2.0)) * pow(max(fma(half(-float(_2277)), _2277, half(1.0)), half(0.0)), half(0.5) * (_2489 * _2485))) * half(0.15915493667125701904296875)) * (_2273 * (_2489 * _1714))) * _1383)) * half3(_2216)), half3(float3(65504.0)));
    out.fragColor = float4(half4(((fma(half4(_1434).xyz, _1413 * _1376, fma(half3(float3(params.facet_diffuseColor)), _1214, half4(_1329).xyz * (mix(half4(_1303).xxx, half4(_1303).yyy, half3(float3(params.facet_f0))) * _1322)) * _1378) + _1540) + _1931) + _2322, half(1.0)));
    return out;
}

