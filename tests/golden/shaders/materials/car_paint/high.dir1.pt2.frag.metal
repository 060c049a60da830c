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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    half3 _955 = normalize(half3(in.v_normal));
    float3 _961 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1264 = max(dot(_955, half3(_961)), half(9.9999997473787516355514526367188e-05));
    half3 _1268 = reflect(-half3(_961), _955);
    float4 _1306 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1264, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1325 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1306).y) - half(1.0)));
    float4 _1282 = facet_environment.sample(facet_environmentSmplr, float3(_1268), level(params.facet_environmentLod));
    half _1371 = half(1.0) - _1264;
    half _1374 = _1371 * _1371;
    half _1381 = fma(half(0.959999978542327880859375), (_1374 * _1374) * _1371, half(0.039999999105930328369140625));
    half _1351 = fma(half(-float(_1381)), half(params.facet_clearCoat), half(1.0));
    float4 _1359 = facet_environment.sample(facet_environmentSmplr, float3(_1268), level(params.facet_clearCoatLod));
    half _1438 = clamp(dot(_955, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    float3 _1509 = fast::normalize(_961 + frame.lightDirection.xyz);
    half _1445 = clamp(dot(_955, half3(_1509)), half(0.0), half(1.0));
    half _1449 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1509)), half(0.0), half(1.0));
    half _1549 = half(4096.0) * half(params.facet_alpha);
    half3 _1568 = cross(_955, half3(_1509)) * half(64.0);
    half _1570 = half(64.0) * half(params.facet_alpha);
    half _1572 = _1570 * _1445;
    half _1575 = dot(_1568, _1568);
    half _1555 = _1549 / fma(_1572, _1572, _1575);
    half _1587 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1593 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1597 = sqrt(fma(_1264 * _1264, _1593, _1587));
    half _1621 = half(1.0) - _1449;
    half _1624 = _1621 * _1621;
    half _1629 = (_1624 * _1624) * _1621;
    half3 _1632 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1716 = half(64.0) * half(params.facet_clearCoatAlpha);
    half _1718 = _1716 * _1445;
    half _1670 = half(12.56637096405029296875) * max(_1449 * _1449, half(6.103515625e-05));
    half _1672 = half(4096.0) * half(params.facet_clearCoatAlpha);
    half _1676 = _1672 / (fma(_1718, _1718, _1575) * _1670);
    half _1694 = half(0.959999978542327880859375) * half(params.facet_clearCoat);
    float3 _1784 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1787 = dot(_1784, _1784);
    float3 _1792 = _1784 * rsqrt(fast::max(_1787, 9.9999999392252902907785028219223e-09));
    float _1796 = _1787 * float(frame.punctualLights[0].positionFalloff.w);
    float _1801 = fast::clamp(fma(-_1796, _1796, 1.0), 0.0, 1.0);
    float _1820 = fast::clamp(fma(dot(-_1792, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1885 = clamp(dot(_955, half3(_1792)), half(0.0), half(1.0));
    float3 _1956 = fast::normalize(_961 + _1792);
    half _1892 = clamp(dot(_955, half3(_1956)), half(0.0), half(1.0));
    half _1896 = clamp(dot(half3(_1792), half3(_1956)), half(0.0), half(1.0));
    half3 _2015 = cross(_955, half3(_1956)) * half(64.0);
    half _2019 = _1570 * _1892;
    half _2022 = dot(_2015, _2015);
    half _2002 = _1549 / fma(_2019, _2019, _2022);
    half _2068 = half(1.0) - _1896;
    half _2071 = _2068 * _2068;
    half _2076 = (_2071 * _2071) * _2068;
    half _2165 = _1716 * _1892;
    half _2117 = half(12.56637096405029296875) * max(_1896 * _1896, half(6.103515625e-05));
    half _2123 = _1672 / (fma(_2165, _2165, _2022) * _2117);
    half3 _1937 = min(min(((((half3(float3(params.facet_f0)) + (_1632 * _2076)) * min(min((_2002 * _2002) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1885, _1597, _1264 * sqrt(fma(_1885 * _1885, _1593, _1587))), half(65504.0)), half(65504.0))) * _1325) * _1351) + half3(min(_2123 * (_2123 * _2117), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1694 * _2076)), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1801) * half(_1801)) / fast::max(_1787, 9.9999997473787516355514526367188e-05)) * half(_1820)) * half(_1820)), float3(65504.0))) * _1885), half3(float3(65504.0)));
    half3 _2195 = (mix(half4(_1282).xyz * (mix(half4(_1306).xxx, half4(_1306).yyy, half3(float3(params.facet_f0))) * _1325), half4(_1359).xyz, half3(_1381 * half(params.facet_clearCoat))) + min(min(((((half3(float3(params.facet_f0)) + (_1632 * _1629)) * min(min((_1555 * _1555) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1438, _1597, _1264 * sqrt(fma(_1438 * _1438, _1593, _1587))), half(65504.0)), half(65504.0))) * _1325) * _1351) + half3(min(_1676 * (_1676 * _1670), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1694 * _1629)), half3(float3(65504.0))) * (half4(frame.lightColor).xyz * _1438), half3(float3(65504.0)))) + _1937;
    float3 _2231 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2234 = dot(_2231, _2231);
    float3 _2239 = _2231 * rsqrt(fast::max(_2234, 9.9999999392252902907785028219223e-09));
    float _2243 = _2234 * float(frame.punctualLights[1].positionFalloff.w);
    float _2248 = fast::clamp(fma(-_2243, _2243, 1.0), 0.0, 1.0);
    float _2267 = fast::clamp(fma(dot(-_2239, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _2332 = clamp(dot(_955, half3(_2239)), half(0.0), half(1.0));
    float3 _2403 = fast::normalize(_961 + _2239);
    half _2339 = clamp(dot(_955, half3(_2403)), half(0.0), half(1.0));
    half _2343 = clamp(dot(half3(_2239), half3(_2403)), half(0.0), half(1.0));
    half3 _2462 = cross(_955, half3(_2403)) * half(64.0);
    half _2466 = _1570 * _2339;
    half _2469 = dot(_2462, _2462);
    half _2449 = _1549 / fma(_2466, _2466, _2469);
    half _2515 = half(1.0) - _2343;
    half _2518 = _2515 * _2515;
    half _2523 = (_2518 * _2518) * _2515;
    half _2612 = _1716 * _2339;
    half _2564 = half(12.56637096405029296875) * max(_2343 * _2343, half(6.103515625e-05));
    half _2570 = _1672 / (fma(_2612, _2612, _2469) * _2564);
    half3 _2384 = min(min(((((half3(float3(params.facet_f0)) + (_1632 * _2523)) * min(min((_2449 * _2449) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2332, _1597, _1264 * sqrt(fma(_2332 * _2332, _1593, _1587))), half(65504.0)), half(65504.0))) * _1325) * _1351) + half3(min(_2570 * (_2570 * _2564), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1694 * _2523)), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2248) * half(_2248)) / fast::max(_2234, 9.9999997473787516355514526367188e-05)) * half(_2267)) * half(_2267)), float3(65504.0))) * _2332), half3(float3(65504.0)));
    half3 _2642 = _2195 + _2384;
    out.fragColor = float4(half4(_2642, half(1.0)));
    return out;
}

