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
    float _1357 = 1.0 - _1246;
    float _1360 = _1357 * _1357;
    float _1372 = fast::clamp(params.coat, 0.0, 1.0);
    float _1377 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1512 = fast::normalize(_939 + frame.lightDirection.xyz);
    float _1444 = fast::clamp(dot(_933, frame.lightDirection.xyz), 0.0, 1.0);
    float _1448 = fast::clamp(dot(_933, _1512), 0.0, 1.0);
    float _1452 = fast::clamp(dot(frame.lightDirection.xyz, _1512), 0.0, 1.0);
    float3 _1550 = cross(_933, _1512);
    float _1553 = _1448 * params.facet_alpha;
    float _1557 = dot(_1550, _1550);
    float _1562 = params.facet_alpha / fma(_1553, _1553, _1557);
    float _1575 = params.facet_alpha * params.facet_alpha;
    float _1581 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1585 = sqrt(fma(_1246 * _1246, _1581, _1575));
    float _1608 = 1.0 - _1452;
    float _1611 = _1608 * _1608;
    float _1616 = (_1611 * _1611) * _1608;
    float3 _1619 = float3(1.0) - float3(params.facet_f0);
    float3 _1470 = frame.lightColor.xyz * _1444;
    float _1691 = fma(0.959999978542327880859375, _1616, 0.039999999105930328369140625);
    float _1656 = _1377 * _1377;
    float _1708 = _1448 * _1656;
    float _1717 = _1656 / fma(_1708, _1708, _1557);
    float3 _1783 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1786 = dot(_1783, _1783);
    float3 _1791 = _1783 * rsqrt(fast::max(_1786, 9.9999999392252902907785028219223e-09));
    float _1795 = _1786 * float(frame.punctualLights[0].positionFalloff.w);
    float _1800 = fast::clamp(fma(-_1795, _1795, 1.0), 0.0, 1.0);
    float _1819 = fast::clamp(fma(dot(-_1791, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1955 = fast::normalize(_939 + _1791);
    float _1887 = fast::clamp(dot(_933, _1791), 0.0, 1.0);
    float _1891 = fast::clamp(dot(_933, _1955), 0.0, 1.0);
    float _1895 = fast::clamp(dot(_1791, _1955), 0.0, 1.0);
    float3 _1993 = cross(_933, _1955);
    float _1996 = _1891 * params.facet_alpha;
    float _2000 = dot(_1993, _1993);
    float _2005 = params.facet_alpha / fma(_1996, _1996, _2000);
    float _2051 = 1.0 - _1895;
    float _2054 = _2051 * _2051;
    float _2059 = (_2054 * _2054) * _2051;
    float3 _1913 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1800 * _1800) / fast::max(_1786, 9.9999997473787516355514526367188e-05)) * _1819) * _1819)) * _1887;
    float _2134 = fma(0.959999978542327880859375, _2059, 0.039999999105930328369140625);
    float _2151 = _1891 * _1656;
    float _2160 = _1656 / fma(_2151, _2151, _2000);
    float3 _2191 = (mix(facet_environment.sample(facet_environmentSmplr, _1250, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1285.xxx, _1285.yyy, float3(params.facet_f0)) * _1304), facet_environment.sample(facet_environmentSmplr, _1250, level(_1377 * 4.0)).xyz, float3(fma(0.959999978542327880859375, (_1360 * _1360) * _1357, 0.039999999105930328369140625) * _1372)) + fast::min(fma(((float3(params.facet_f0) + (_1619 * _1616)) * (((_1562 * _1562) * 0.3183098733425140380859375) * (0.5 / fma(_1444, _1585, _1246 * sqrt(fma(_1444 * _1444, _1581, _1575)))))) * _1304, _1470 * fma(-_1691, _1372, 1.0), _1470 * ((((_1717 * _1717) * 0.3183098733425140380859375) * (0.25 / fast::max(_1452 * _1452, 6.103515625e-05))) * (_1691 * _1372))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1619 * _2059)) * (((_2005 * _2005) * 0.3183098733425140380859375) * (0.5 / fma(_1887, _1585, _1246 * sqrt(fma(_1887 * _1887, _1581, _1575)))))) * _1304, _1913 * fma(-_2134, _1372, 1.0), _1913 * ((((_2160 * _2160) * 0.3183098733425140380859375) * (0.25 / fast::max(_1895 * _1895, 6.103515625e-05))) * (_2134 * _1372))), float3(65504.0));
    float3 _2226 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2229 = dot(_2226, _2226);
    float3 _2234 = _2226 * rsqrt(fast::max(_2229, 9.9999999392252902907785028219223e-09));
    float _2238 = _2229 * float(frame.punctualLights[1].positionFalloff.w);
    float _2243 = fast::clamp(fma(-_2238, _2238, 1.0), 0.0, 1.0);
    float _2262 = fast::clamp(fma(dot(-_2234, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2398 = fast::normalize(_939 + _2234);
    float _2330 = fast::clamp(dot(_933, _2234), 0.0, 1.0);
    float _2334 = fast::clamp(dot(_933, _2398), 0.0, 1.0);
    float _2338 = fast::clamp(dot(_2234, _2398), 0.0, 1.0);
    float3 _2436 = cross(_933, _2398);
    float _2439 = _2334 * params.facet_alpha;
    float _2443 = dot(_2436, _2436);
    float _2448 = params.facet_alpha / fma(_2439, _2439, _2443);
    float _2494 = 1.0 - _2338;
    float _2497 = _2494 * _2494;
    float _2502 = (_2497 * _2497) * _2494;
    float3 _2356 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2243 * _2243) / fast::max(_2229, 9.9999997473787516355514526367188e-05)) * _2262) * _2262)) * _2330;
    float _2577 = fma(0.959999978542327880859375, _2502, 0.039999999105930328369140625);
    float _2594 = _2334 * _1656;
    float _2603 = _1656 / fma(_2594, _2594, _2443);
    out.fragColor = float4(_2191 + fast::min(fma(((float3(params.facet_f0) + (_1619 * _2502)) * (((_2448 * _2448) * 0.3183098733425140380859375) * (0.5 / fma(_2330, _1585, _1246 * sqrt(fma(_2330 * _2330, _1581, _1575)))))) * _1304, _2356 * fma(-_2577, _1372, 1.0), _2356 * ((((_2603 * _2603) * 0.3183098733425140380859375) * (0.25 / fast::max(_2338 * _2338, 6.103515625e-05))) * (_2577 * _1372))), float3(65504.0)), 1.0);
    return out;
}

