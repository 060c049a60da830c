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
    float3 _933 = fast::normalize(in.v_normal);
    float3 _939 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1246 = fast::max(dot(_933, _939), 9.9999997473787516355514526367188e-05);
    float3 _1250 = reflect(-_939, _933);
    float4 _1285 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1246, params.facet_perceptualRoughness), level(0.0));
    float3 _1304 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1285.y) - 1.0));
    float _1359 = 1.0 - _1246;
    float _1362 = _1359 * _1359;
    float _1369 = fma(0.959999978542327880859375, (_1362 * _1362) * _1359, 0.039999999105930328369140625);
    float _1374 = fast::clamp(params.coat, 0.0, 1.0);
    float _1341 = fma(-_1369, _1374, 1.0);
    float _1379 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1510 = fast::normalize(_939 + frame.lightDirection.xyz);
    float _1444 = fast::clamp(dot(_933, frame.lightDirection.xyz), 0.0, 1.0);
    float _1448 = fast::clamp(dot(_933, _1510), 0.0, 1.0);
    float _1452 = fast::clamp(dot(frame.lightDirection.xyz, _1510), 0.0, 1.0);
    float3 _1548 = cross(_933, _1510);
    float _1551 = _1448 * params.facet_alpha;
    float _1555 = dot(_1548, _1548);
    float _1560 = params.facet_alpha / fma(_1551, _1551, _1555);
    float _1573 = params.facet_alpha * params.facet_alpha;
    float _1579 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1583 = sqrt(fma(_1246 * _1246, _1579, _1573));
    float _1606 = 1.0 - _1452;
    float _1609 = _1606 * _1606;
    float _1614 = (_1609 * _1609) * _1606;
    float3 _1617 = float3(1.0) - float3(params.facet_f0);
    float3 _1470 = frame.lightColor.xyz * _1444;
    float _1655 = _1379 * _1379;
    float _1707 = _1448 * _1655;
    float _1716 = _1655 / fma(_1707, _1707, _1555);
    float3 _1782 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1785 = dot(_1782, _1782);
    float3 _1790 = _1782 * rsqrt(fast::max(_1785, 9.9999999392252902907785028219223e-09));
    float _1794 = _1785 * float(frame.punctualLights[0].positionFalloff.w);
    float _1799 = fast::clamp(fma(-_1794, _1794, 1.0), 0.0, 1.0);
    float _1818 = fast::clamp(fma(dot(-_1790, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1950 = fast::normalize(_939 + _1790);
    float _1884 = fast::clamp(dot(_933, _1790), 0.0, 1.0);
    float _1888 = fast::clamp(dot(_933, _1950), 0.0, 1.0);
    float _1892 = fast::clamp(dot(_1790, _1950), 0.0, 1.0);
    float3 _1988 = cross(_933, _1950);
    float _1991 = _1888 * params.facet_alpha;
    float _1995 = dot(_1988, _1988);
    float _2000 = params.facet_alpha / fma(_1991, _1991, _1995);
    float _2046 = 1.0 - _1892;
    float _2049 = _2046 * _2046;
    float _2054 = (_2049 * _2049) * _2046;
    float3 _1910 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1799 * _1799) / fast::max(_1785, 9.9999997473787516355514526367188e-05)) * _1818) * _1818)) * _1884;
    float _2147 = _1888 * _1655;
    float _2156 = _1655 / fma(_2147, _2147, _1995);
    float3 _2222 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2225 = dot(_2222, _2222);
    float3 _2230 = _2222 * rsqrt(fast::max(_2225, 9.9999999392252902907785028219223e-09));
    float _2234 = _2225 * float(frame.punctualLights[1].positionFalloff.w);
    float _2239 = fast::clamp(fma(-_2234, _2234, 1.0), 0.0, 1.0);
    float _2258 = fast::clamp(fma(dot(-_2230, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2390 = fast::normalize(_939 + _2230);
    float _2324 = fast::clamp(dot(_933, _2230), 0.0, 1.0);
    float _2328 = fast::clamp(dot(_933, _2390), 0.0, 1.0);
    float _2332 = fast::clamp(dot(_2230, _2390), 0.0, 1.0);
    float3 _2428 = cross(_933, _2390);
    float _2431 = _2328 * params.facet_alpha;
    float _2435 = dot(_2428, _2428);
    float _2440 = params.facet_alpha / fma(_2431, _2431, _2435);
    float _2486 = 1.0 - _2332;
    float _2489 = _2486 * _2486;
    float _2494 = (_2489 * _2489) * _2486;
    float3 _2350 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2239 * _2239) / fast::max(_2225, 9.9999997473787516355514526367188e-05)) * _2258) * _2258)) * _2324;
    float _2587 = _2328 * _1655;
    float _2596 = _1655 / fma(_2587, _2587, _2435);
    float3 _2627 = ((mix(facet_environment.sample(facet_environmentSmplr, _1250, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1285.xxx, _1285.yyy, float3(params.facet_f0)) * _1304), facet_environment.sample(facet_environmentSmplr, _1250, level(_1379 * 4.0)).xyz, float3(_1369 * _1374)) + fast::min(fma(((float3(params.facet_f0) + (_1617 * _1614)) * (((_1560 * _1560) * 0.3183098733425140380859375) * (0.5 / fma(_1444, _1583, _1246 * sqrt(fma(_1444 * _1444, _1579, _1573)))))) * _1304, _1470 * _1341, _1470 * ((((_1716 * _1716) * 0.3183098733425140380859375) * (0.25 / fast::max(_1452 * _1452, 6.103515625e-05))) * (fma(0.959999978542327880859375, _1614, 0.039999999105930328369140625) * _1374))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1617 * _2054)) * (((_2000 * _2000) * 0.3183098733425140380859375) * (0.5 / fma(_1884, _1583, _1246 * sqrt(fma(_1884 * _1884, _1579, _1573)))))) * _1304, _1910 * _1341, _1910 * ((((_2156 * _2156) * 0.3183098733425140380859375) * (0.25 / fast::max(_1892 * _1892, 6.103515625e-05))) * (fma(0.959999978542327880859375, _2054, 0.039999999105930328369140625) * _1374))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1617 * _2494)) * (((_2440 * _2440) * 0.3183098733425140380859375) * (0.5 / fma(_2324, _1583, _1246 * sqrt(fma(_2324 * _2324, _1579, _1573)))))) * _1304, _2350 * _1341, _2350 * ((((_2596 * _2596) * 0.3183098733425140380859375) * (0.25 / fast::max(_2332 * _2332, 6.103515625e-05))) * (fma(0.959999978542327880859375, _2494, 0.039999999105930328369140625) * _1374))), float3(65504.0));
    out.fragColor = float4(_2627, 1.0);
    return out;
}

