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
    half3 _958 = normalize(half3(in.v_normal));
    float3 _964 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1268 = max(dot(_958, half3(_964)), half(9.9999997473787516355514526367188e-05));
    half3 _1272 = reflect(-half3(_964), _958);
    float4 _1307 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1268, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1326 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1307).y) - half(1.0)));
    float4 _1333 = facet_environment.sample(facet_environmentSmplr, float3(_1272), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1381 = half(1.0) - _1268;
    half _1384 = _1381 * _1381;
    half _1391 = fma(half(0.959999978542327880859375), (_1384 * _1384) * _1381, half(0.039999999105930328369140625));
    half _1396 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1363 = fma(half(-float(_1391)), _1396, half(1.0));
    half _1401 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1408 = facet_environment.sample(facet_environmentSmplr, float3(_1272), level(_1401 * half(4.0)));
    float3 _1533 = fast::normalize(_964 + frame.lightDirection.xyz);
    half _1466 = clamp(dot(_958, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1470 = clamp(dot(_958, half3(_1533)), half(0.0), half(1.0));
    half _1474 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1533)), half(0.0), half(1.0));
    half3 _1573 = cross(_958, half3(_1533));
    half _1576 = _1470 * half(params.facet_alpha);
    half _1580 = dot(_1573, _1573);
    half _1585 = half(params.facet_alpha) / fma(_1576, _1576, _1580);
    half _1599 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1605 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1609 = sqrt(fma(_1268 * _1268, _1605, _1599));
    half _1633 = half(1.0) - _1474;
    half _1636 = _1633 * _1633;
    half _1641 = (_1636 * _1636) * _1633;
    half3 _1644 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1492 = half4(frame.lightColor).xyz * _1466;
    half _1678 = _1401 * _1401;
    half _1684 = _1470 * _1678;
    half _1695 = max(_1474 * _1474, half(6.103515625e-05));
    half _1698 = half(2048.0) * _1678;
    half _1703 = _1698 / (fma(_1684, _1684, _1580) * (_1695 * half(25735.927734375)));
    float3 _1802 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1805 = dot(_1802, _1802);
    float3 _1810 = _1802 * rsqrt(fast::max(_1805, 9.9999999392252902907785028219223e-09));
    float _1814 = _1805 * float(frame.punctualLights[0].positionFalloff.w);
    float _1819 = fast::clamp(fma(-_1814, _1814, 1.0), 0.0, 1.0);
    float _1838 = fast::clamp(fma(dot(-_1810, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1974 = fast::normalize(_964 + _1810);
    half _1907 = clamp(dot(_958, half3(_1810)), half(0.0), half(1.0));
    half _1911 = clamp(dot(_958, half3(_1974)), half(0.0), half(1.0));
    half _1915 = clamp(dot(half3(_1810), half3(_1974)), half(0.0), half(1.0));
    half3 _2014 = cross(_958, half3(_1974));
    half _2017 = _1911 * half(params.facet_alpha);
    half _2021 = dot(_2014, _2014);
    half _2026 = half(params.facet_alpha) / fma(_2017, _2017, _2021);
    half _2074 = half(1.0) - _1915;
    half _2077 = _2074 * _2074;
    half _2082 = (_2077 * _2077) * _2074;
    half3 _1933 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1819) * half(_1819)) / fast::max(_1805, 9.9999997473787516355514526367188e-05)) * half(_1838)) * half(_1838)), float3(65504.0))) * _1907;
    half _2125 = _1911 * _1678;
    half _2136 = max(_1915 * _1915, half(6.103515625e-05));
    half _2144 = _1698 / (fma(_2125, _2125, _2021) * (_2136 * half(25735.927734375)));
    half3 _2207 = (mix(half4(_1333).xyz * (mix(half4(_1307).xxx, half4(_1307).yyy, half3(float3(params.facet_f0))) * _1326), half4(_1408).xyz, half3(_1391 * _1396)) + min(fma(((half3(float3(params.facet_f0)) + (_1644 * _1641)) * min(min((_1585 * _1585) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1466, _1609, _1268 * sqrt(fma(_1466 * _1466, _1605, _1599))), half(65504.0)), half(65504.0))) * _1326, _1492 * _1363, _1492 * (min(_1703 * (_1703 * (half(12.56637096405029296875) * _1695)), half(65504.0)) * (fma(half(0.959999978542327880859375), _1641, half(0.039999999105930328369140625)) * _1396))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1644 * _2082)) * min(min((_2026 * _2026) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1907, _1609, _1268 * sqrt(fma(_1907 * _1907, _1605, _1599))), half(65504.0)), half(65504.0))) * _1326, _1933 * _1363, _1933 * (min(_2144 * (_2144 * (half(12.56637096405029296875) * _2136)), half(65504.0)) * (fma(half(0.959999978542327880859375), _2082, half(0.039999999105930328369140625)) * _1396))), half3(float3(65504.0)));
    float3 _2243 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2246 = dot(_2243, _2243);
    float3 _2251 = _2243 * rsqrt(fast::max(_2246, 9.9999999392252902907785028219223e-09));
    float _2255 = _2246 * float(frame.punctualLights[1].positionFalloff.w);
    float _2260 = fast::clamp(fma(-_2255, _2255, 1.0), 0.0, 1.0);
    float _2279 = fast::clamp(fma(dot(-_2251, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2415 = fast::normalize(_964 + _2251);
    half _2348 = clamp(dot(_958, half3(_2251)), half(0.0), half(1.0));
    half _2352 = clamp(dot(_958, half3(_2415)), half(0.0), half(1.0));
    half _2356 = clamp(dot(half3(_2251), half3(_2415)), half(0.0), half(1.0));
    half3 _2455 = cross(_958, half3(_2415));
    half _2458 = _2352 * half(params.facet_alpha);
    half _2462 = dot(_2455, _2455);
    half _2467 = half(params.facet_alpha) / fma(_2458, _2458, _2462);
    half _2515 = half(1.0) - _2356;
    half _2518 = _2515 * _2515;
    half _2523 = (_2518 * _2518) * _2515;
    half3 _2374 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2260) * half(_2260)) / fast::max(_2246, 9.9999997473787516355514526367188e-05)) * half(_2279)) * half(_2279)), float3(65504.0))) * _2348;
    half _2566 = _2352 * _1678;
    half _2577 = max(_2356 * _2356, half(6.103515625e-05));
    half _2585 = _1698 / (fma(_2566, _2566, _2462) * (_2577 * half(25735.927734375)));
    out.fragColor = float4(half4(_2207 + min(fma(((half3(float3(params.facet_f0)) + (_1644 * _2523)) * min(min((_2467 * _2467) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2348, _1609, _1268 * sqrt(fma(_2348 * _2348, _1605, _1599))), half(65504.0)), half(65504.0))) * _1326, _2374 * _1363, _2374 * (min(_2585 * (_2585 * (half(12.56637096405029296875) * _2577)), half(65504.0)) * (fma(half(0.959999978542327880859375), _2523, half(0.039999999105930328369140625)) * _1396))), half3(float3(65504.0))), half(1.0)));
    return out;
}

