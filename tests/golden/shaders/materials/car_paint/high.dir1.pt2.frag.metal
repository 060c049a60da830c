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
    half _1369 = half(1.0) - _1256;
    half _1372 = _1369 * _1369;
    half _1379 = fma(half(0.959999978542327880859375), (_1372 * _1372) * _1369, half(0.039999999105930328369140625));
    half _1384 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1351 = fma(half(-float(_1379)), _1384, half(1.0));
    half _1389 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1396 = facet_environment.sample(facet_environmentSmplr, float3(_1260), level(_1389 * half(4.0)));
    float3 _1521 = fast::normalize(_949 + frame.lightDirection.xyz);
    half _1454 = clamp(dot(_943, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1458 = clamp(dot(_943, half3(_1521)), half(0.0), half(1.0));
    half _1462 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1521)), half(0.0), half(1.0));
    half3 _1561 = cross(_943, half3(_1521));
    half _1564 = _1458 * half(params.facet_alpha);
    half _1568 = dot(_1561, _1561);
    half _1573 = half(params.facet_alpha) / fma(_1564, _1564, _1568);
    half _1587 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1593 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1597 = sqrt(fma(_1256 * _1256, _1593, _1587));
    half _1621 = half(1.0) - _1462;
    half _1624 = _1621 * _1621;
    half _1629 = (_1624 * _1624) * _1621;
    half3 _1632 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1480 = half4(frame.lightColor).xyz * _1454;
    half _1670 = _1389 * _1389;
    half _1723 = _1458 * _1670;
    half _1732 = _1670 / fma(_1723, _1723, _1568);
    float3 _1800 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1803 = dot(_1800, _1800);
    float3 _1808 = _1800 * rsqrt(fast::max(_1803, 9.9999999392252902907785028219223e-09));
    float _1812 = _1803 * float(frame.punctualLights[0].positionFalloff.w);
    float _1817 = fast::clamp(fma(-_1812, _1812, 1.0), 0.0, 1.0);
    float _1836 = fast::clamp(fma(dot(-_1808, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1972 = fast::normalize(_949 + _1808);
    half _1905 = clamp(dot(_943, half3(_1808)), half(0.0), half(1.0));
    half _1909 = clamp(dot(_943, half3(_1972)), half(0.0), half(1.0));
    half _1913 = clamp(dot(half3(_1808), half3(_1972)), half(0.0), half(1.0));
    half3 _2012 = cross(_943, half3(_1972));
    half _2015 = _1909 * half(params.facet_alpha);
    half _2019 = dot(_2012, _2012);
    half _2024 = half(params.facet_alpha) / fma(_2015, _2015, _2019);
    half _2072 = half(1.0) - _1913;
    half _2075 = _2072 * _2072;
    half _2080 = (_2075 * _2075) * _2072;
    half3 _1931 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1817) * half(_1817)) / fast::max(_1803, 9.9999997473787516355514526367188e-05)) * half(_1836)) * half(_1836)), float3(65504.0))) * _1905;
    half _2174 = _1909 * _1670;
    half _2183 = _1670 / fma(_2174, _2174, _2019);
    half3 _2215 = (mix(half4(_1321).xyz * (mix(half4(_1295).xxx, half4(_1295).yyy, half3(float3(params.facet_f0))) * _1314), half4(_1396).xyz, half3(_1379 * _1384)) + min(fma(((half3(float3(params.facet_f0)) + (_1632 * _1629)) * min(min((_1573 * _1573) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1454, _1597, _1256 * sqrt(fma(_1454 * _1454, _1593, _1587))), half(65504.0)), half(65504.0))) * _1314, _1480 * _1351, _1480 * (min(min((_1732 * _1732) * half(0.3183098733425140380859375), half(65504.0)) * (half(0.25) / max(_1462 * _1462, half(6.103515625e-05))), half(65504.0)) * (fma(half(0.959999978542327880859375), _1629, half(0.039999999105930328369140625)) * _1384))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1632 * _2080)) * min(min((_2024 * _2024) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1905, _1597, _1256 * sqrt(fma(_1905 * _1905, _1593, _1587))), half(65504.0)), half(65504.0))) * _1314, _1931 * _1351, _1931 * (min(min((_2183 * _2183) * half(0.3183098733425140380859375), half(65504.0)) * (half(0.25) / max(_1913 * _1913, half(6.103515625e-05))), half(65504.0)) * (fma(half(0.959999978542327880859375), _2080, half(0.039999999105930328369140625)) * _1384))), half3(float3(65504.0)));
    float3 _2251 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2254 = dot(_2251, _2251);
    float3 _2259 = _2251 * rsqrt(fast::max(_2254, 9.9999999392252902907785028219223e-09));
    float _2263 = _2254 * float(frame.punctualLights[1].positionFalloff.w);
    float _2268 = fast::clamp(fma(-_2263, _2263, 1.0), 0.0, 1.0);
    float _2287 = fast::clamp(fma(dot(-_2259, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2423 = fast::normalize(_949 + _2259);
    half _2356 = clamp(dot(_943, half3(_2259)), half(0.0), half(1.0));
    half _2360 = clamp(dot(_943, half3(_2423)), half(0.0), half(1.0));
    half _2364 = clamp(dot(half3(_2259), half3(_2423)), half(0.0), half(1.0));
    half3 _2463 = cross(_943, half3(_2423));
    half _2466 = _2360 * half(params.facet_alpha);
    half _2470 = dot(_2463, _2463);
    half _2475 = half(params.facet_alpha) / fma(_2466, _2466, _2470);
    half _2523 = half(1.0) - _2364;
    half _2526 = _2523 * _2523;
    half _2531 = (_2526 * _2526) * _2523;
    half3 _2382 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2268) * half(_2268)) / fast::max(_2254, 9.9999997473787516355514526367188e-05)) * half(_2287)) * half(_2287)), float3(65504.0))) * _2356;
    half _2625 = _2360 * _1670;
    half _2634 = _1670 / fma(_2625, _2625, _2470);
    float4 _2992 = float4(half4(_2215 + min(fma(((half3(float3(params.facet_f0)) + (_1632 * _2531)) * min(min((_2475 * _2475) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2356, _1597, _1256 * sqrt(fma(_2356 * _2356, _1593, _1587))), half(65504.0)), half(65504.0))) * _1314, _2382 * _1351, _2382 * (min(min((_2634 * _2634) * half(0.3183098733425140380859375), half(65504.0)) * (half(0.25) / max(_2364 * _2364, half(6.103515625e-05))), half(65504.0)) * (fma(half(0.959999978542327880859375), _2531, half(0.039999999105930328369140625)) * _1384))), half3(float3(65504.0))), half(1.0)));
    out.fragColor = _2992;
    return out;
}

