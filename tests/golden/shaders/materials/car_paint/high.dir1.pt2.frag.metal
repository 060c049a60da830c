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
    half3 _943 = normalize(half3(in.v_normal));
    float3 _949 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1256 = max(dot(_943, half3(_949)), half(9.9999997473787516355514526367188e-05));
    half3 _1260 = reflect(-half3(_949), _943);
    float4 _1295 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1256, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1314 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1295).y) - half(1.0)));
    float4 _1321 = facet_environment.sample(facet_environmentSmplr, float3(_1260), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1367 = half(1.0) - _1256;
    half _1370 = _1367 * _1367;
    half _1382 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1387 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1394 = facet_environment.sample(facet_environmentSmplr, float3(_1260), level(_1387 * half(4.0)));
    float3 _1523 = fast::normalize(_949 + frame.lightDirection.xyz);
    half _1454 = clamp(dot(_943, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1458 = clamp(dot(_943, half3(_1523)), half(0.0), half(1.0));
    half _1462 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1523)), half(0.0), half(1.0));
    half3 _1563 = cross(_943, half3(_1523));
    half _1566 = _1458 * half(params.facet_alpha);
    half _1570 = dot(_1563, _1563);
    half _1575 = half(params.facet_alpha) / fma(_1566, _1566, _1570);
    half _1589 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1595 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1599 = sqrt(fma(_1256 * _1256, _1595, _1589));
    half _1623 = half(1.0) - _1462;
    half _1626 = _1623 * _1623;
    half _1631 = (_1626 * _1626) * _1623;
    half3 _1634 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1480 = half4(frame.lightColor).xyz * _1454;
    half _1707 = fma(half(0.959999978542327880859375), _1631, half(0.039999999105930328369140625));
    half _1671 = _1387 * _1387;
    half _1724 = _1458 * _1671;
    half _1733 = _1671 / fma(_1724, _1724, _1570);
    float3 _1801 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1804 = dot(_1801, _1801);
    float3 _1809 = _1801 * rsqrt(fast::max(_1804, 9.9999999392252902907785028219223e-09));
    float _1813 = _1804 * float(frame.punctualLights[0].positionFalloff.w);
    float _1818 = fast::clamp(fma(-_1813, _1813, 1.0), 0.0, 1.0);
    float _1837 = fast::clamp(fma(dot(-_1809, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1977 = fast::normalize(_949 + _1809);
    half _1908 = clamp(dot(_943, half3(_1809)), half(0.0), half(1.0));
    half _1912 = clamp(dot(_943, half3(_1977)), half(0.0), half(1.0));
    half _1916 = clamp(dot(half3(_1809), half3(_1977)), half(0.0), half(1.0));
    half3 _2017 = cross(_943, half3(_1977));
    half _2020 = _1912 * half(params.facet_alpha);
    half _2024 = dot(_2017, _2017);
    half _2029 = half(params.facet_alpha) / fma(_2020, _2020, _2024);
    half _2077 = half(1.0) - _1916;
    half _2080 = _2077 * _2077;
    half _2085 = (_2080 * _2080) * _2077;
    half3 _1934 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1818) * half(_1818)) / fast::max(_1804, 9.9999997473787516355514526367188e-05)) * half(_1837)) * half(_1837)), float3(65504.0))) * _1908;
    half _2161 = fma(half(0.959999978542327880859375), _2085, half(0.039999999105930328369140625));
    half _2178 = _1912 * _1671;
    half _2187 = _1671 / fma(_2178, _2178, _2024);
    half3 _2219 = (mix(half4(_1321).xyz * (mix(half4(_1295).xxx, half4(_1295).yyy, half3(float3(params.facet_f0))) * _1314), half4(_1394).xyz, half3(fma(half(0.959999978542327880859375), (_1370 * _1370) * _1367, half(0.039999999105930328369140625)) * _1382)) + min(fma(((half3(float3(params.facet_f0)) + (_1634 * _1631)) * min(min((_1575 * _1575) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1454, _1599, _1256 * sqrt(fma(_1454 * _1454, _1595, _1589))), half(65504.0)), half(65504.0))) * _1314, _1480 * fma(half(-float(_1707)), _1382, half(1.0)), _1480 * (min(min((_1733 * _1733) * half(0.3183098733425140380859375), half(65504.0)) * (half(0.25) / max(_1462 * _1462, half(6.103515625e-05))), half(65504.0)) * (_1707 * _1382))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1634 * _2085)) * min(min((_2029 * _2029) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1908, _1599, _1256 * sqrt(fma(_1908 * _1908, _1595, _1589))), half(65504.0)), half(65504.0))) * _1314, _1934 * fma(half(-float(_2161)), _1382, half(1.0)), _1934 * (min(min((_2187 * _2187) * half(0.3183098733425140380859375), half(65504.0)) * (half(0.25) / max(_1916 * _1916, half(6.103515625e-05))), half(65504.0)) * (_2161 * _1382))), half3(float3(65504.0)));
    float3 _2255 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2258 = dot(_2255, _2255);
    float3 _2263 = _2255 * rsqrt(fast::max(_2258, 9.9999999392252902907785028219223e-09));
    float _2267 = _2258 * float(frame.punctualLights[1].positionFalloff.w);
    float _2272 = fast::clamp(fma(-_2267, _2267, 1.0), 0.0, 1.0);
    float _2291 = fast::clamp(fma(dot(-_2263, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2431 = fast::normalize(_949 + _2263);
    half _2362 = clamp(dot(_943, half3(_2263)), half(0.0), half(1.0));
    half _2366 = clamp(dot(_943, half3(_2431)), half(0.0), half(1.0));
    half _2370 = clamp(dot(half3(_2263), half3(_2431)), half(0.0), half(1.0));
    half3 _2471 = cross(_943, half3(_2431));
    half _2474 = _2366 * half(params.facet_alpha);
    half _2478 = dot(_2471, _2471);
    half _2483 = half(params.facet_alpha) / fma(_2474, _2474, _2478);
    half _2531 = half(1.0) - _2370;
    half _2534 = _2531 * _2531;
    half _2539 = (_2534 * _2534) * _2531;
    half3 _2388 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2272) * half(_2272)) / fast::max(_2258, 9.9999997473787516355514526367188e-05)) * half(_2291)) * half(_2291)), float3(65504.0))) * _2362;
    half _2615 = fma(half(0.959999978542327880859375), _2539, half(0.039999999105930328369140625));
    half _2632 = _2366 * _1671;
    half _2641 = _1671 / fma(_2632, _2632, _2478);
    half3 _2673 = _2219 + min(fma(((half3(float3(params.facet_f0)) + (_1634 * _2539)) * min(min((_2483 * _2483) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2362, _1599, _1256 * sqrt(fma(_2362 * _2362, _1595, _1589))), half(65504.0)), half(65504.0))) * _1314, _2388 * fma(half(-float(_2615)), _1382, half(1.0)), _2388 * (min(min((_2641 * _2641) * half(0.3183098733425140380859375), half(65504.0)) * (half(0.25) / max(_2370 * _2370, half(6.103515625e-05))), half(65504.0)) * (_2615 * _1382))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2673, half(1.0)));
    return out;
}

