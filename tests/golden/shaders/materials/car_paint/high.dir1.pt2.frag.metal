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
    float facet_clearCoat;
    float facet_clearCoatAlpha;
    float facet_clearCoatLod;
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
    half3 _969 = normalize(half3(in.v_normal));
    float3 _975 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1280 = max(dot(_969, half3(_975)), half(9.9999997473787516355514526367188e-05));
    half3 _1284 = reflect(-half3(_975), _969);
    float4 _1319 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1280, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1338 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1319).y) - half(1.0)));
    float4 _1348 = facet_environment.sample(facet_environmentSmplr, float3(_1284), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1395 = half(1.0) - _1280;
    half _1398 = _1395 * _1395;
    half _1405 = fma(half(0.959999978542327880859375), (_1398 * _1398) * _1395, half(0.039999999105930328369140625));
    half _1375 = fma(half(-float(_1405)), half(params.facet_clearCoat), half(1.0));
    float4 _1383 = facet_environment.sample(facet_environmentSmplr, float3(_1284), level(params.facet_clearCoatLod));
    float3 _1533 = fast::normalize(_975 + frame.lightDirection.xyz);
    half _1465 = clamp(dot(_969, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1469 = clamp(dot(_969, half3(_1533)), half(0.0), half(1.0));
    half _1473 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1533)), half(0.0), half(1.0));
    half _1573 = half(4096.0) * half(params.facet_alpha);
    half3 _1592 = cross(_969, half3(_1533)) * half(64.0);
    half _1594 = half(64.0) * half(params.facet_alpha);
    half _1596 = _1594 * _1469;
    half _1599 = dot(_1592, _1592);
    half _1579 = _1573 / fma(_1596, _1596, _1599);
    half _1611 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1617 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1621 = sqrt(fma(_1280 * _1280, _1617, _1611));
    half _1645 = half(1.0) - _1473;
    half _1648 = _1645 * _1645;
    half _1653 = (_1648 * _1648) * _1645;
    half3 _1656 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1740 = half(64.0) * half(params.facet_clearCoatAlpha);
    half _1742 = _1740 * _1469;
    half _1694 = half(12.56637096405029296875) * max(_1473 * _1473, half(6.103515625e-05));
    half _1696 = half(4096.0) * half(params.facet_clearCoatAlpha);
    half _1700 = _1696 / (fma(_1742, _1742, _1599) * _1694);
    half _1718 = half(0.959999978542327880859375) * half(params.facet_clearCoat);
    float3 _1808 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1811 = dot(_1808, _1808);
    float3 _1816 = _1808 * rsqrt(fast::max(_1811, 9.9999999392252902907785028219223e-09));
    float _1820 = _1811 * float(frame.punctualLights[0].positionFalloff.w);
    float _1825 = fast::clamp(fma(-_1820, _1820, 1.0), 0.0, 1.0);
    float _1844 = fast::clamp(fma(dot(-_1816, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1980 = fast::normalize(_975 + _1816);
    half _1912 = clamp(dot(_969, half3(_1816)), half(0.0), half(1.0));
    half _1916 = clamp(dot(_969, half3(_1980)), half(0.0), half(1.0));
    half _1920 = clamp(dot(half3(_1816), half3(_1980)), half(0.0), half(1.0));
    half3 _2039 = cross(_969, half3(_1980)) * half(64.0);
    half _2043 = _1594 * _1916;
    half _2046 = dot(_2039, _2039);
    half _2026 = _1573 / fma(_2043, _2043, _2046);
    half _2092 = half(1.0) - _1920;
    half _2095 = _2092 * _2092;
    half _2100 = (_2095 * _2095) * _2092;
    half _2189 = _1740 * _1916;
    half _2141 = half(12.56637096405029296875) * max(_1920 * _1920, half(6.103515625e-05));
    half _2147 = _1696 / (fma(_2189, _2189, _2046) * _2141);
    half3 _1961 = min(min(((((half3(float3(params.facet_f0)) + (_1656 * _2100)) * min(min((_2026 * _2026) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1912, _1621, _1280 * sqrt(fma(_1912 * _1912, _1617, _1611))), half(65504.0)), half(65504.0))) * _1338) * _1375) + half3(min(_2147 * (_2147 * _2141), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1718 * _2100)), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1825) * half(_1825)) / fast::max(_1811, 9.9999997473787516355514526367188e-05)) * half(_1844)) * half(_1844)), float3(65504.0))) * _1912), half3(float3(65504.0)));
    half3 _2219 = (mix(half4(_1348).xyz * (mix(half4(_1319).xxx, half4(_1319).yyy, half3(float3(params.facet_f0))) * _1338), half4(_1383).xyz, half3(_1405 * half(params.facet_clearCoat))) + min(min(((((half3(float3(params.facet_f0)) + (_1656 * _1653)) * min(min((_1579 * _1579) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1465, _1621, _1280 * sqrt(fma(_1465 * _1465, _1617, _1611))), half(65504.0)), half(65504.0))) * _1338) * _1375) + half3(min(_1700 * (_1700 * _1694), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1718 * _1653)), half3(float3(65504.0))) * (half4(frame.lightColor).xyz * _1465), half3(float3(65504.0)))) + _1961;
    float3 _2255 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2258 = dot(_2255, _2255);
    float3 _2263 = _2255 * rsqrt(fast::max(_2258, 9.9999999392252902907785028219223e-09));
    float _2267 = _2258 * float(frame.punctualLights[1].positionFalloff.w);
    float _2272 = fast::clamp(fma(-_2267, _2267, 1.0), 0.0, 1.0);
    float _2291 = fast::clamp(fma(dot(-_2263, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2427 = fast::normalize(_975 + _2263);
    half _2359 = clamp(dot(_969, half3(_2263)), half(0.0), half(1.0));
    half _2363 = clamp(dot(_969, half3(_2427)), half(0.0), half(1.0));
    half _2367 = clamp(dot(half3(_2263), half3(_2427)), half(0.0), half(1.0));
    half3 _2486 = cross(_969, half3(_2427)) * half(64.0);
    half _2490 = _1594 * _2363;
    half _2493 = dot(_2486, _2486);
    half _2473 = _1573 / fma(_2490, _2490, _2493);
    half _2539 = half(1.0) - _2367;
    half _2542 = _2539 * _2539;
    half _2547 = (_2542 * _2542) * _2539;
    half _2636 = _1740 * _2363;
    half _2588 = half(12.56637096405029296875) * max(_2367 * _2367, half(6.103515625e-05));
    half _2594 = _1696 / (fma(_2636, _2636, _2493) * _2588);
    half3 _2408 = min(min(((((half3(float3(params.facet_f0)) + (_1656 * _2547)) * min(min((_2473 * _2473) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2359, _1621, _1280 * sqrt(fma(_2359 * _2359, _1617, _1611))), half(65504.0)), half(65504.0))) * _1338) * _1375) + half3(min(_2594 * (_2594 * _2588), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1718 * _2547)), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2272) * half(_2272)) / fast::max(_2258, 9.9999997473787516355514526367188e-05)) * half(_2291)) * half(_2291)), float3(65504.0))) * _2359), half3(float3(65504.0)));
    half3 _2666 = _2219 + _2408;
    out.fragColor = float4(half4(_2666, half(1.0)));
    return out;
}

