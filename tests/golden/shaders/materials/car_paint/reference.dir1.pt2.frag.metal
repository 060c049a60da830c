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
    float3 _962 = fast::normalize(in.v_normal);
    float3 _968 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1272 = fast::max(dot(_962, _968), 9.9999997473787516355514526367188e-05);
    float3 _1276 = reflect(-_968, _962);
    float4 _1311 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1272, params.facet_perceptualRoughness), level(0.0));
    float3 _1330 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1311.y) - 1.0));
    float _1385 = 1.0 - _1272;
    float _1388 = _1385 * _1385;
    float _1395 = fma(0.959999978542327880859375, (_1388 * _1388) * _1385, 0.039999999105930328369140625);
    float _1400 = fast::clamp(params.coat, 0.0, 1.0);
    float _1367 = fma(-_1395, _1400, 1.0);
    float _1405 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1536 = fast::normalize(_968 + frame.lightDirection.xyz);
    float _1470 = fast::clamp(dot(_962, frame.lightDirection.xyz), 0.0, 1.0);
    float _1474 = fast::clamp(dot(_962, _1536), 0.0, 1.0);
    float _1478 = fast::clamp(dot(frame.lightDirection.xyz, _1536), 0.0, 1.0);
    float _1575 = 4096.0 * params.facet_alpha;
    float3 _1594 = cross(_962, _1536) * 64.0;
    float _1597 = 64.0 * params.facet_alpha;
    float _1598 = _1474 * _1597;
    float _1601 = dot(_1594, _1594);
    float _1581 = _1575 / fma(_1598, _1598, _1601);
    float _1613 = params.facet_alpha * params.facet_alpha;
    float _1619 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1623 = sqrt(fma(_1272 * _1272, _1619, _1613));
    float _1646 = 1.0 - _1478;
    float _1649 = _1646 * _1646;
    float _1654 = (_1649 * _1649) * _1646;
    float3 _1657 = float3(1.0) - float3(params.facet_f0);
    float3 _1496 = frame.lightColor.xyz * _1470;
    float _1693 = _1405 * _1405;
    float _1742 = 64.0 * _1693;
    float _1743 = _1474 * _1742;
    float _1703 = 12.56637096405029296875 * fast::max(_1478 * _1478, 6.103515625e-05);
    float _1705 = 4096.0 * _1693;
    float _1709 = _1705 / (fma(_1743, _1743, _1601) * _1703);
    float3 _1825 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1828 = dot(_1825, _1825);
    float3 _1833 = _1825 * rsqrt(fast::max(_1828, 9.9999999392252902907785028219223e-09));
    float _1837 = _1828 * float(frame.punctualLights[0].positionFalloff.w);
    float _1842 = fast::clamp(fma(-_1837, _1837, 1.0), 0.0, 1.0);
    float _1861 = fast::clamp(fma(dot(-_1833, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1993 = fast::normalize(_968 + _1833);
    float _1927 = fast::clamp(dot(_962, _1833), 0.0, 1.0);
    float _1931 = fast::clamp(dot(_962, _1993), 0.0, 1.0);
    float _1935 = fast::clamp(dot(_1833, _1993), 0.0, 1.0);
    float3 _2051 = cross(_962, _1993) * 64.0;
    float _2055 = _1931 * _1597;
    float _2058 = dot(_2051, _2051);
    float _2038 = _1575 / fma(_2055, _2055, _2058);
    float _2103 = 1.0 - _1935;
    float _2106 = _2103 * _2103;
    float _2111 = (_2106 * _2106) * _2103;
    float3 _1953 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1842 * _1842) / fast::max(_1828, 9.9999997473787516355514526367188e-05)) * _1861) * _1861)) * _1927;
    float _2200 = _1931 * _1742;
    float _2160 = 12.56637096405029296875 * fast::max(_1935 * _1935, 6.103515625e-05);
    float _2166 = _1705 / (fma(_2200, _2200, _2058) * _2160);
    float3 _2282 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2285 = dot(_2282, _2282);
    float3 _2290 = _2282 * rsqrt(fast::max(_2285, 9.9999999392252902907785028219223e-09));
    float _2294 = _2285 * float(frame.punctualLights[1].positionFalloff.w);
    float _2299 = fast::clamp(fma(-_2294, _2294, 1.0), 0.0, 1.0);
    float _2318 = fast::clamp(fma(dot(-_2290, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2450 = fast::normalize(_968 + _2290);
    float _2384 = fast::clamp(dot(_962, _2290), 0.0, 1.0);
    float _2388 = fast::clamp(dot(_962, _2450), 0.0, 1.0);
    float _2392 = fast::clamp(dot(_2290, _2450), 0.0, 1.0);
    float3 _2508 = cross(_962, _2450) * 64.0;
    float _2512 = _2388 * _1597;
    float _2515 = dot(_2508, _2508);
    float _2495 = _1575 / fma(_2512, _2512, _2515);
    float _2560 = 1.0 - _2392;
    float _2563 = _2560 * _2560;
    float _2568 = (_2563 * _2563) * _2560;
    float3 _2410 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2299 * _2299) / fast::max(_2285, 9.9999997473787516355514526367188e-05)) * _2318) * _2318)) * _2384;
    float _2657 = _2388 * _1742;
    float _2617 = 12.56637096405029296875 * fast::max(_2392 * _2392, 6.103515625e-05);
    float _2623 = _1705 / (fma(_2657, _2657, _2515) * _2617);
    float3 _2704 = ((mix(facet_environment.sample(facet_environmentSmplr, _1276, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1311.xxx, _1311.yyy, float3(params.facet_f0)) * _1330), facet_environment.sample(facet_environmentSmplr, _1276, level(_1405 * 4.0)).xyz, float3(_1395 * _1400)) + fast::min(fma(((float3(params.facet_f0) + (_1657 * _1654)) * (((_1581 * _1581) * 0.3183098733425140380859375) * (0.5 / fma(_1470, _1623, _1272 * sqrt(fma(_1470 * _1470, _1619, _1613)))))) * _1330, _1496 * _1367, _1496 * ((_1709 * (_1709 * _1703)) * (fma(0.959999978542327880859375, _1654, 0.039999999105930328369140625) * _1400))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1657 * _2111)) * (((_2038 * _2038) * 0.3183098733425140380859375) * (0.5 / fma(_1927, _1623, _1272 * sqrt(fma(_1927 * _1927, _1619, _1613)))))) * _1330, _1953 * _1367, _1953 * ((_2166 * (_2166 * _2160)) * (fma(0.959999978542327880859375, _2111, 0.039999999105930328369140625) * _1400))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1657 * _2568)) * (((_2495 * _2495) * 0.3183098733425140380859375) * (0.5 / fma(_2384, _1623, _1272 * sqrt(fma(_2384 * _2384, _1619, _1613)))))) * _1330, _2410 * _1367, _2410 * ((_2623 * (_2623 * _2617)) * (fma(0.959999978542327880859375, _2568, 0.039999999105930328369140625) * _1400))), float3(65504.0));
    out.fragColor = float4(_2704, 1.0);
    return out;
}

