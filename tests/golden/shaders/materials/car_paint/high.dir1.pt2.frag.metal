#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
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
    half3 _976 = normalize(half3(in.v_normal));
    float3 _982 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1286 = max(dot(_976, half3(_982)), half(9.9999997473787516355514526367188e-05));
    half3 _1290 = reflect(-half3(_982), _976);
    float4 _1325 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1286, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1344 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1325).y) - half(1.0)));
    float4 _1354 = facet_environment.sample(facet_environmentSmplr, float3(_1290), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1402 = half(1.0) - _1286;
    half _1405 = _1402 * _1402;
    half _1412 = fma(half(0.959999978542327880859375), (_1405 * _1405) * _1402, half(0.039999999105930328369140625));
    half _1417 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1384 = fma(half(-float(_1412)), _1417, half(1.0));
    half _1422 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1432 = facet_environment.sample(facet_environmentSmplr, float3(_1290), level(_1422 * (half(4.0) * (half(2.0) - _1422))));
    float3 _1557 = fast::normalize(_982 + frame.lightDirection.xyz);
    half _1489 = clamp(dot(_976, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1493 = clamp(dot(_976, half3(_1557)), half(0.0), half(1.0));
    half _1497 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1557)), half(0.0), half(1.0));
    half _1597 = half(4096.0) * half(params.facet_alpha);
    half3 _1616 = cross(_976, half3(_1557)) * half(64.0);
    half _1618 = half(64.0) * half(params.facet_alpha);
    half _1620 = _1618 * _1493;
    half _1623 = dot(_1616, _1616);
    half _1603 = _1597 / fma(_1620, _1620, _1623);
    half _1635 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1641 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1645 = sqrt(fma(_1286 * _1286, _1641, _1635));
    half _1669 = half(1.0) - _1497;
    half _1672 = _1669 * _1669;
    half _1677 = (_1672 * _1672) * _1669;
    half3 _1680 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1712 = _1422 * _1422;
    half _1769 = half(64.0) * _1712;
    half _1771 = _1769 * _1493;
    half _1722 = half(12.56637096405029296875) * max(_1497 * _1497, half(6.103515625e-05));
    half _1724 = half(4096.0) * _1712;
    half _1728 = _1724 / (fma(_1771, _1771, _1623) * _1722);
    half _1746 = half(0.959999978542327880859375) * _1417;
    float3 _1838 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1841 = dot(_1838, _1838);
    float3 _1846 = _1838 * rsqrt(fast::max(_1841, 9.9999999392252902907785028219223e-09));
    float _1850 = _1841 * float(frame.punctualLights[0].positionFalloff.w);
    float _1855 = fast::clamp(fma(-_1850, _1850, 1.0), 0.0, 1.0);
    float _1874 = fast::clamp(fma(dot(-_1846, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2010 = fast::normalize(_982 + _1846);
    half _1942 = clamp(dot(_976, half3(_1846)), half(0.0), half(1.0));
    half _1946 = clamp(dot(_976, half3(_2010)), half(0.0), half(1.0));
    half _1950 = clamp(dot(half3(_1846), half3(_2010)), half(0.0), half(1.0));
    half3 _2069 = cross(_976, half3(_2010)) * half(64.0);
    half _2073 = _1618 * _1946;
    half _2076 = dot(_2069, _2069);
    half _2056 = _1597 / fma(_2073, _2073, _2076);
    half _2122 = half(1.0) - _1950;
    half _2125 = _2122 * _2122;
    half _2130 = (_2125 * _2125) * _2122;
    half _2224 = _1769 * _1946;
    half _2175 = half(12.56637096405029296875) * max(_1950 * _1950, half(6.103515625e-05));
    half _2181 = _1724 / (fma(_2224, _2224, _2076) * _2175);
    half3 _1991 = min(min(((((half3(float3(params.facet_f0)) + (_1680 * _2130)) * min(min((_2056 * _2056) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1942, _1645, _1286 * sqrt(fma(_1942 * _1942, _1641, _1635))), half(65504.0)), half(65504.0))) * _1344) * _1384) + half3(min(_2181 * (_2181 * _2175), half(65504.0)) * fma(half(0.039999999105930328369140625), _1417, _1746 * _2130)), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1855) * half(_1855)) / fast::max(_1841, 9.9999997473787516355514526367188e-05)) * half(_1874)) * half(_1874)), float3(65504.0))) * _1942), half3(float3(65504.0)));
    half3 _2255 = (mix(half4(_1354).xyz * (mix(half4(_1325).xxx, half4(_1325).yyy, half3(float3(params.facet_f0))) * _1344), half4(_1432).xyz, half3(_1412 * _1417)) + min(min(((((half3(float3(params.facet_f0)) + (_1680 * _1677)) * min(min((_1603 * _1603) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1489, _1645, _1286 * sqrt(fma(_1489 * _1489, _1641, _1635))), half(65504.0)), half(65504.0))) * _1344) * _1384) + half3(min(_1728 * (_1728 * _1722), half(65504.0)) * fma(half(0.039999999105930328369140625), _1417, _1746 * _1677)), half3(float3(65504.0))) * (half4(frame.lightColor).xyz * _1489), half3(float3(65504.0)))) + _1991;
    float3 _2291 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2294 = dot(_2291, _2291);
    float3 _2299 = _2291 * rsqrt(fast::max(_2294, 9.9999999392252902907785028219223e-09));
    float _2303 = _2294 * float(frame.punctualLights[1].positionFalloff.w);
    float _2308 = fast::clamp(fma(-_2303, _2303, 1.0), 0.0, 1.0);
    float _2327 = fast::clamp(fma(dot(-_2299, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2463 = fast::normalize(_982 + _2299);
    half _2395 = clamp(dot(_976, half3(_2299)), half(0.0), half(1.0));
    half _2399 = clamp(dot(_976, half3(_2463)), half(0.0), half(1.0));
    half _2403 = clamp(dot(half3(_2299), half3(_2463)), half(0.0), half(1.0));
    half3 _2522 = cross(_976, half3(_2463)) * half(64.0);
    half _2526 = _1618 * _2399;
    half _2529 = dot(_2522, _2522);
    half _2509 = _1597 / fma(_2526, _2526, _2529);
    half _2575 = half(1.0) - _2403;
    half _2578 = _2575 * _2575;
    half _2583 = (_2578 * _2578) * _2575;
    half _2677 = _1769 * _2399;
    half _2628 = half(12.56637096405029296875) * max(_2403 * _2403, half(6.103515625e-05));
    half _2634 = _1724 / (fma(_2677, _2677, _2529) * _2628);
    half3 _2444 = min(min(((((half3(float3(params.facet_f0)) + (_1680 * _2583)) * min(min((_2509 * _2509) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2395, _1645, _1286 * sqrt(fma(_2395 * _2395, _1641, _1635))), half(65504.0)), half(65504.0))) * _1344) * _1384) + half3(min(_2634 * (_2634 * _2628), half(65504.0)) * fma(half(0.039999999105930328369140625), _1417, _1746 * _2583)), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2308) * half(_2308)) / fast::max(_2294, 9.9999997473787516355514526367188e-05)) * half(_2327)) * half(_2327)), float3(65504.0))) * _2395), half3(float3(65504.0)));
    half3 _2708 = _2255 + _2444;
    out.fragColor = float4(half4(_2708, half(1.0)));
    return out;
}

