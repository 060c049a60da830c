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
    half _1271 = max(dot(_958, half3(_964)), half(9.9999997473787516355514526367188e-05));
    half3 _1275 = reflect(-half3(_964), _958);
    float4 _1310 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1271, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1329 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1310).y) - half(1.0)));
    float4 _1336 = facet_environment.sample(facet_environmentSmplr, float3(_1275), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1384 = half(1.0) - _1271;
    half _1387 = _1384 * _1384;
    half _1394 = fma(half(0.959999978542327880859375), (_1387 * _1387) * _1384, half(0.039999999105930328369140625));
    half _1399 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1366 = fma(half(-float(_1394)), _1399, half(1.0));
    half _1404 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1411 = facet_environment.sample(facet_environmentSmplr, float3(_1275), level(_1404 * half(4.0)));
    float3 _1536 = fast::normalize(_964 + frame.lightDirection.xyz);
    half _1469 = clamp(dot(_958, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1473 = clamp(dot(_958, half3(_1536)), half(0.0), half(1.0));
    half _1477 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1536)), half(0.0), half(1.0));
    half3 _1576 = cross(_958, half3(_1536));
    half _1579 = _1473 * half(params.facet_alpha);
    half _1583 = dot(_1576, _1576);
    half _1588 = half(params.facet_alpha) / fma(_1579, _1579, _1583);
    half _1602 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1608 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1612 = sqrt(fma(_1271 * _1271, _1608, _1602));
    half _1636 = half(1.0) - _1477;
    half _1639 = _1636 * _1636;
    half _1644 = (_1639 * _1639) * _1636;
    half3 _1647 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1495 = half4(frame.lightColor).xyz * _1469;
    half _1681 = _1404 * _1404;
    half _1687 = _1473 * _1681;
    half _1698 = max(_1477 * _1477, half(6.103515625e-05));
    half _1701 = half(2048.0) * _1681;
    half _1706 = _1701 / (fma(_1687, _1687, _1583) * (_1698 * half(25735.927734375)));
    float3 _1805 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1808 = dot(_1805, _1805);
    float3 _1813 = _1805 * rsqrt(fast::max(_1808, 9.9999999392252902907785028219223e-09));
    float _1817 = _1808 * float(frame.punctualLights[0].positionFalloff.w);
    float _1822 = fast::clamp(fma(-_1817, _1817, 1.0), 0.0, 1.0);
    float _1841 = fast::clamp(fma(dot(-_1813, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1977 = fast::normalize(_964 + _1813);
    half _1910 = clamp(dot(_958, half3(_1813)), half(0.0), half(1.0));
    half _1914 = clamp(dot(_958, half3(_1977)), half(0.0), half(1.0));
    half _1918 = clamp(dot(half3(_1813), half3(_1977)), half(0.0), half(1.0));
    half3 _2017 = cross(_958, half3(_1977));
    half _2020 = _1914 * half(params.facet_alpha);
    half _2024 = dot(_2017, _2017);
    half _2029 = half(params.facet_alpha) / fma(_2020, _2020, _2024);
    half _2077 = half(1.0) - _1918;
    half _2080 = _2077 * _2077;
    half _2085 = (_2080 * _2080) * _2077;
    half3 _1936 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1822) * half(_1822)) / fast::max(_1808, 9.9999997473787516355514526367188e-05)) * half(_1841)) * half(_1841)), float3(65504.0))) * _1910;
    half _2128 = _1914 * _1681;
    half _2139 = max(_1918 * _1918, half(6.103515625e-05));
    half _2147 = _1701 / (fma(_2128, _2128, _2024) * (_2139 * half(25735.927734375)));
    half3 _2210 = (mix(half4(_1336).xyz * (mix(half4(_1310).xxx, half4(_1310).yyy, half3(float3(params.facet_f0))) * _1329), half4(_1411).xyz, half3(_1394 * _1399)) + min(fma(((half3(float3(params.facet_f0)) + (_1647 * _1644)) * min(min((_1588 * _1588) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1469, _1612, _1271 * sqrt(fma(_1469 * _1469, _1608, _1602))), half(65504.0)), half(65504.0))) * _1329, _1495 * _1366, _1495 * (min(_1706 * (_1706 * (half(12.56637096405029296875) * _1698)), half(65504.0)) * (fma(half(0.959999978542327880859375), _1644, half(0.039999999105930328369140625)) * _1399))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1647 * _2085)) * min(min((_2029 * _2029) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1910, _1612, _1271 * sqrt(fma(_1910 * _1910, _1608, _1602))), half(65504.0)), half(65504.0))) * _1329, _1936 * _1366, _1936 * (min(_2147 * (_2147 * (half(12.56637096405029296875) * _2139)), half(65504.0)) * (fma(half(0.959999978542327880859375), _2085, half(0.039999999105930328369140625)) * _1399))), half3(float3(65504.0)));
    float3 _2246 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2249 = dot(_2246, _2246);
    float3 _2254 = _2246 * rsqrt(fast::max(_2249, 9.9999999392252902907785028219223e-09));
    float _2258 = _2249 * float(frame.punctualLights[1].positionFalloff.w);
    float _2263 = fast::clamp(fma(-_2258, _2258, 1.0), 0.0, 1.0);
    float _2282 = fast::clamp(fma(dot(-_2254, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2418 = fast::normalize(_964 + _2254);
    half _2351 = clamp(dot(_958, half3(_2254)), half(0.0), half(1.0));
    half _2355 = clamp(dot(_958, half3(_2418)), half(0.0), half(1.0));
    half _2359 = clamp(dot(half3(_2254), half3(_2418)), half(0.0), half(1.0));
    half3 _2458 = cross(_958, half3(_2418));
    half _2461 = _2355 * half(params.facet_alpha);
    half _2465 = dot(_2458, _2458);
    half _2470 = half(params.facet_alpha) / fma(_2461, _2461, _2465);
    half _2518 = half(1.0) - _2359;
    half _2521 = _2518 * _2518;
    half _2526 = (_2521 * _2521) * _2518;
    half3 _2377 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2263) * half(_2263)) / fast::max(_2249, 9.9999997473787516355514526367188e-05)) * half(_2282)) * half(_2282)), float3(65504.0))) * _2351;
    half _2569 = _2355 * _1681;
    half _2580 = max(_2359 * _2359, half(6.103515625e-05));
    half _2588 = _1701 / (fma(_2569, _2569, _2465) * (_2580 * half(25735.927734375)));
    out.fragColor = float4(half4(_2210 + min(fma(((half3(float3(params.facet_f0)) + (_1647 * _2526)) * min(min((_2470 * _2470) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2351, _1612, _1271 * sqrt(fma(_2351 * _2351, _1608, _1602))), half(65504.0)), half(65504.0))) * _1329, _2377 * _1366, _2377 * (min(_2588 * (_2588 * (half(12.56637096405029296875) * _2580)), half(65504.0)) * (fma(half(0.959999978542327880859375), _2526, half(0.039999999105930328369140625)) * _1399))), half3(float3(65504.0))), half(1.0)));
    return out;
}

