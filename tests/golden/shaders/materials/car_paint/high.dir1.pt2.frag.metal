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
    half3 _979 = normalize(half3(in.v_normal));
    float3 _985 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1289 = max(dot(_979, half3(_985)), half(9.9999997473787516355514526367188e-05));
    half3 _1293 = reflect(-half3(_985), _979);
    float4 _1328 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1289, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1347 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1328).y) - half(1.0)));
    float4 _1357 = facet_environment.sample(facet_environmentSmplr, float3(_1293), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1404 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1410 = half(1.0) - _1289;
    half _1413 = _1410 * _1410;
    half _1417 = half(0.959999978542327880859375) * _1404;
    half _1424 = fma(half(0.039999999105930328369140625), _1404, _1417 * ((_1413 * _1413) * _1410));
    half _1387 = half(1.0) - _1424;
    half _1429 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1439 = facet_environment.sample(facet_environmentSmplr, float3(_1293), level(_1429 * (half(4.0) * (half(2.0) - _1429))));
    float3 _1564 = fast::normalize(_985 + frame.lightDirection.xyz);
    half _1497 = clamp(dot(_979, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1501 = clamp(dot(_979, half3(_1564)), half(0.0), half(1.0));
    half _1505 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1564)), half(0.0), half(1.0));
    half _1604 = half(4096.0) * half(params.facet_alpha);
    half3 _1623 = cross(_979, half3(_1564)) * half(64.0);
    half _1625 = half(64.0) * half(params.facet_alpha);
    half _1627 = _1625 * _1501;
    half _1630 = dot(_1623, _1623);
    half _1610 = _1604 / fma(_1627, _1627, _1630);
    half _1642 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1648 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1652 = sqrt(fma(_1289 * _1289, _1648, _1642));
    half _1676 = half(1.0) - _1505;
    half _1679 = _1676 * _1676;
    half _1684 = (_1679 * _1679) * _1676;
    half3 _1687 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1523 = half4(frame.lightColor).xyz * _1497;
    half _1724 = _1429 * _1429;
    half _1772 = half(64.0) * _1724;
    half _1774 = _1772 * _1501;
    half _1734 = half(12.56637096405029296875) * max(_1505 * _1505, half(6.103515625e-05));
    half _1736 = half(4096.0) * _1724;
    half _1740 = _1736 / (fma(_1774, _1774, _1630) * _1734);
    float3 _1861 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1864 = dot(_1861, _1861);
    float3 _1869 = _1861 * rsqrt(fast::max(_1864, 9.9999999392252902907785028219223e-09));
    float _1873 = _1864 * float(frame.punctualLights[0].positionFalloff.w);
    float _1878 = fast::clamp(fma(-_1873, _1873, 1.0), 0.0, 1.0);
    float _1897 = fast::clamp(fma(dot(-_1869, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2033 = fast::normalize(_985 + _1869);
    half _1966 = clamp(dot(_979, half3(_1869)), half(0.0), half(1.0));
    half _1970 = clamp(dot(_979, half3(_2033)), half(0.0), half(1.0));
    half _1974 = clamp(dot(half3(_1869), half3(_2033)), half(0.0), half(1.0));
    half3 _2092 = cross(_979, half3(_2033)) * half(64.0);
    half _2096 = _1625 * _1970;
    half _2099 = dot(_2092, _2092);
    half _2079 = _1604 / fma(_2096, _2096, _2099);
    half _2145 = half(1.0) - _1974;
    half _2148 = _2145 * _2145;
    half _2153 = (_2148 * _2148) * _2145;
    half3 _1992 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1878) * half(_1878)) / fast::max(_1864, 9.9999997473787516355514526367188e-05)) * half(_1897)) * half(_1897)), float3(65504.0))) * _1966;
    half _2243 = _1772 * _1970;
    half _2203 = half(12.56637096405029296875) * max(_1974 * _1974, half(6.103515625e-05));
    half _2209 = _1736 / (fma(_2243, _2243, _2099) * _2203);
    half3 _2294 = (mix(half4(_1357).xyz * (mix(half4(_1328).xxx, half4(_1328).yyy, half3(float3(params.facet_f0))) * _1347), half4(_1439).xyz, half3(_1424)) + min(fma(((half3(float3(params.facet_f0)) + (_1687 * _1684)) * min(min((_1610 * _1610) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1497, _1652, _1289 * sqrt(fma(_1497 * _1497, _1648, _1642))), half(65504.0)), half(65504.0))) * _1347, _1523 * _1387, _1523 * (min(_1740 * (_1740 * _1734), half(65504.0)) * fma(half(0.039999999105930328369140625), _1404, _1417 * _1684))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1687 * _2153)) * min(min((_2079 * _2079) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1966, _1652, _1289 * sqrt(fma(_1966 * _1966, _1648, _1642))), half(65504.0)), half(65504.0))) * _1347, _1992 * _1387, _1992 * (min(_2209 * (_2209 * _2203), half(65504.0)) * fma(half(0.039999999105930328369140625), _1404, _1417 * _2153))), half3(float3(65504.0)));
    float3 _2330 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2333 = dot(_2330, _2330);
    float3 _2338 = _2330 * rsqrt(fast::max(_2333, 9.9999999392252902907785028219223e-09));
    float _2342 = _2333 * float(frame.punctualLights[1].positionFalloff.w);
    float _2347 = fast::clamp(fma(-_2342, _2342, 1.0), 0.0, 1.0);
    float _2366 = fast::clamp(fma(dot(-_2338, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2502 = fast::normalize(_985 + _2338);
    half _2435 = clamp(dot(_979, half3(_2338)), half(0.0), half(1.0));
    half _2439 = clamp(dot(_979, half3(_2502)), half(0.0), half(1.0));
    half _2443 = clamp(dot(half3(_2338), half3(_2502)), half(0.0), half(1.0));
    half3 _2561 = cross(_979, half3(_2502)) * half(64.0);
    half _2565 = _1625 * _2439;
    half _2568 = dot(_2561, _2561);
    half _2548 = _1604 / fma(_2565, _2565, _2568);
    half _2614 = half(1.0) - _2443;
    half _2617 = _2614 * _2614;
    half _2622 = (_2617 * _2617) * _2614;
    half3 _2461 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2347) * half(_2347)) / fast::max(_2333, 9.9999997473787516355514526367188e-05)) * half(_2366)) * half(_2366)), float3(65504.0))) * _2435;
    half _2712 = _1772 * _2439;
    half _2672 = half(12.56637096405029296875) * max(_2443 * _2443, half(6.103515625e-05));
    half _2678 = _1736 / (fma(_2712, _2712, _2568) * _2672);
    out.fragColor = float4(half4(_2294 + min(fma(((half3(float3(params.facet_f0)) + (_1687 * _2622)) * min(min((_2548 * _2548) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2435, _1652, _1289 * sqrt(fma(_2435 * _2435, _1648, _1642))), half(65504.0)), half(65504.0))) * _1347, _2461 * _1387, _2461 * (min(_2678 * (_2678 * _2672), half(65504.0)) * fma(half(0.039999999105930328369140625), _1404, _1417 * _2622))), half3(float3(65504.0))), half(1.0)));
    return out;
}

