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
    float3 _945 = fast::normalize(in.v_normal);
    float3 _951 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1254 = fast::max(dot(_945, _951), 9.9999997473787516355514526367188e-05);
    float3 _1258 = reflect(-_951, _945);
    float4 _1296 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1254, params.facet_perceptualRoughness), level(0.0));
    float3 _1315 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1296.y) - 1.0));
    float _1361 = 1.0 - _1254;
    float _1364 = _1361 * _1361;
    float _1371 = fma(0.959999978542327880859375, (_1364 * _1364) * _1361, 0.039999999105930328369140625);
    float _1341 = fma(-_1371, params.facet_clearCoat, 1.0);
    float _1428 = fast::clamp(dot(_945, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1498 = fast::normalize(_951 + frame.lightDirection.xyz);
    float _1435 = fast::clamp(dot(_945, _1498), 0.0, 1.0);
    float _1439 = fast::clamp(dot(frame.lightDirection.xyz, _1498), 0.0, 1.0);
    float _1536 = 4096.0 * params.facet_alpha;
    float3 _1554 = cross(_945, _1498) * 64.0;
    float _1556 = 64.0 * params.facet_alpha;
    float _1558 = _1556 * _1435;
    float _1561 = dot(_1554, _1554);
    float _1542 = _1536 / fma(_1558, _1558, _1561);
    float _1573 = params.facet_alpha * params.facet_alpha;
    float _1579 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1583 = sqrt(fma(_1254 * _1254, _1579, _1573));
    float _1606 = 1.0 - _1439;
    float _1609 = _1606 * _1606;
    float _1614 = (_1609 * _1609) * _1606;
    float3 _1617 = float3(1.0) - float3(params.facet_f0);
    float _1700 = 64.0 * params.facet_clearCoatAlpha;
    float _1702 = _1700 * _1435;
    float _1655 = 12.56637096405029296875 * fast::max(_1439 * _1439, 6.103515625e-05);
    float _1657 = 4096.0 * params.facet_clearCoatAlpha;
    float _1661 = _1657 / (fma(_1702, _1702, _1561) * _1655);
    float _1678 = 0.959999978542327880859375 * params.facet_clearCoat;
    float3 _1767 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1770 = dot(_1767, _1767);
    float3 _1775 = _1767 * rsqrt(fast::max(_1770, 9.9999999392252902907785028219223e-09));
    float _1779 = _1770 * float(frame.punctualLights[0].positionFalloff.w);
    float _1784 = fast::clamp(fma(-_1779, _1779, 1.0), 0.0, 1.0);
    float _1803 = fast::clamp(fma(dot(-_1775, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1865 = fast::clamp(dot(_945, _1775), 0.0, 1.0);
    float3 _1935 = fast::normalize(_951 + _1775);
    float _1872 = fast::clamp(dot(_945, _1935), 0.0, 1.0);
    float _1876 = fast::clamp(dot(_1775, _1935), 0.0, 1.0);
    float3 _1991 = cross(_945, _1935) * 64.0;
    float _1995 = _1556 * _1872;
    float _1998 = dot(_1991, _1991);
    float _1979 = _1536 / fma(_1995, _1995, _1998);
    float _2043 = 1.0 - _1876;
    float _2046 = _2043 * _2043;
    float _2051 = (_2046 * _2046) * _2043;
    float _2139 = _1700 * _1872;
    float _2092 = 12.56637096405029296875 * fast::max(_1876 * _1876, 6.103515625e-05);
    float _2098 = _1657 / (fma(_2139, _2139, _1998) * _2092);
    float3 _2169 = (mix(facet_environment.sample(facet_environmentSmplr, _1258, level(params.facet_environmentLod)).xyz * (mix(_1296.xxx, _1296.yyy, float3(params.facet_f0)) * _1315), facet_environment.sample(facet_environmentSmplr, _1258, level(params.facet_clearCoatLod)).xyz, float3(_1371 * params.facet_clearCoat)) + fast::min(fast::min(((((float3(params.facet_f0) + (_1617 * _1614)) * (((_1542 * _1542) * 0.3183098733425140380859375) * (0.5 / fma(_1428, _1583, _1254 * sqrt(fma(_1428 * _1428, _1579, _1573)))))) * _1315) * _1341) + float3((_1661 * (_1661 * _1655)) * fma(0.039999999105930328369140625, params.facet_clearCoat, _1678 * _1614)), float3(65504.0)) * (frame.lightColor.xyz * _1428), float3(65504.0))) + fast::min(fast::min(((((float3(params.facet_f0) + (_1617 * _2051)) * (((_1979 * _1979) * 0.3183098733425140380859375) * (0.5 / fma(_1865, _1583, _1254 * sqrt(fma(_1865 * _1865, _1579, _1573)))))) * _1315) * _1341) + float3((_2098 * (_2098 * _2092)) * fma(0.039999999105930328369140625, params.facet_clearCoat, _1678 * _2051)), float3(65504.0)) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1784 * _1784) / fast::max(_1770, 9.9999997473787516355514526367188e-05)) * _1803) * _1803)) * _1865), float3(65504.0));
    float3 _2204 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2207 = dot(_2204, _2204);
    float3 _2212 = _2204 * rsqrt(fast::max(_2207, 9.9999999392252902907785028219223e-09));
    float _2216 = _2207 * float(frame.punctualLights[1].positionFalloff.w);
    float _2221 = fast::clamp(fma(-_2216, _2216, 1.0), 0.0, 1.0);
    float _2240 = fast::clamp(fma(dot(-_2212, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _2302 = fast::clamp(dot(_945, _2212), 0.0, 1.0);
    float3 _2372 = fast::normalize(_951 + _2212);
    float _2309 = fast::clamp(dot(_945, _2372), 0.0, 1.0);
    float _2313 = fast::clamp(dot(_2212, _2372), 0.0, 1.0);
    float3 _2428 = cross(_945, _2372) * 64.0;
    float _2432 = _1556 * _2309;
    float _2435 = dot(_2428, _2428);
    float _2416 = _1536 / fma(_2432, _2432, _2435);
    float _2480 = 1.0 - _2313;
    float _2483 = _2480 * _2480;
    float _2488 = (_2483 * _2483) * _2480;
    float _2576 = _1700 * _2309;
    float _2529 = 12.56637096405029296875 * fast::max(_2313 * _2313, 6.103515625e-05);
    float _2535 = _1657 / (fma(_2576, _2576, _2435) * _2529);
    out.fragColor = float4(_2169 + fast::min(fast::min(((((float3(params.facet_f0) + (_1617 * _2488)) * (((_2416 * _2416) * 0.3183098733425140380859375) * (0.5 / fma(_2302, _1583, _1254 * sqrt(fma(_2302 * _2302, _1579, _1573)))))) * _1315) * _1341) + float3((_2535 * (_2535 * _2529)) * fma(0.039999999105930328369140625, params.facet_clearCoat, _1678 * _2488)), float3(65504.0)) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2221 * _2221) / fast::max(_2207, 9.9999997473787516355514526367188e-05)) * _2240) * _2240)) * _2302), float3(65504.0)), 1.0);
    return out;
}

