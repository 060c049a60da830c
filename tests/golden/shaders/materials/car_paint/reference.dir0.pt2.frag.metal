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
    float3 _969 = fast::normalize(in.v_normal);
    float3 _975 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1258 = fast::max(dot(_969, _975), 9.9999997473787516355514526367188e-05);
    float3 _1262 = reflect(-_975, _969);
    float4 _1297 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1258, params.facet_perceptualRoughness), level(0.0));
    float3 _1316 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1297.y) - 1.0));
    float _1373 = fast::clamp(params.coat, 0.0, 1.0);
    float _1379 = 1.0 - _1258;
    float _1382 = _1379 * _1379;
    float _1386 = 0.959999978542327880859375 * _1373;
    float _1393 = fma(0.039999999105930328369140625, _1373, _1386 * ((_1382 * _1382) * _1379));
    float _1356 = 1.0 - _1393;
    float _1398 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1444 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1447 = dot(_1444, _1444);
    float3 _1452 = _1444 * rsqrt(fast::max(_1447, 9.9999999392252902907785028219223e-09));
    float _1456 = _1447 * float(frame.punctualLights[0].positionFalloff.w);
    float _1461 = fast::clamp(fma(-_1456, _1456, 1.0), 0.0, 1.0);
    float _1480 = fast::clamp(fma(dot(-_1452, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1612 = fast::normalize(_975 + _1452);
    float _1546 = fast::clamp(dot(_969, _1452), 0.0, 1.0);
    float _1550 = fast::clamp(dot(_969, _1612), 0.0, 1.0);
    float _1554 = fast::clamp(dot(_1452, _1612), 0.0, 1.0);
    float _1650 = 4096.0 * params.facet_alpha;
    float3 _1668 = cross(_969, _1612) * 64.0;
    float _1670 = 64.0 * params.facet_alpha;
    float _1672 = _1670 * _1550;
    float _1675 = dot(_1668, _1668);
    float _1656 = _1650 / fma(_1672, _1672, _1675);
    float _1687 = params.facet_alpha * params.facet_alpha;
    float _1693 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1697 = sqrt(fma(_1258 * _1258, _1693, _1687));
    float _1720 = 1.0 - _1554;
    float _1723 = _1720 * _1720;
    float _1728 = (_1723 * _1723) * _1720;
    float3 _1731 = float3(1.0) - float3(params.facet_f0);
    float3 _1572 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1461 * _1461) / fast::max(_1447, 9.9999997473787516355514526367188e-05)) * _1480) * _1480)) * _1546;
    float _1768 = _1398 * _1398;
    float _1815 = 64.0 * _1768;
    float _1817 = _1815 * _1550;
    float _1778 = 12.56637096405029296875 * fast::max(_1554 * _1554, 6.103515625e-05);
    float _1780 = 4096.0 * _1768;
    float _1784 = _1780 / (fma(_1817, _1817, _1675) * _1778);
    float3 _1903 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1906 = dot(_1903, _1903);
    float3 _1911 = _1903 * rsqrt(fast::max(_1906, 9.9999999392252902907785028219223e-09));
    float _1915 = _1906 * float(frame.punctualLights[1].positionFalloff.w);
    float _1920 = fast::clamp(fma(-_1915, _1915, 1.0), 0.0, 1.0);
    float _1939 = fast::clamp(fma(dot(-_1911, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2071 = fast::normalize(_975 + _1911);
    float _2005 = fast::clamp(dot(_969, _1911), 0.0, 1.0);
    float _2009 = fast::clamp(dot(_969, _2071), 0.0, 1.0);
    float _2013 = fast::clamp(dot(_1911, _2071), 0.0, 1.0);
    float3 _2127 = cross(_969, _2071) * 64.0;
    float _2131 = _1670 * _2009;
    float _2134 = dot(_2127, _2127);
    float _2115 = _1650 / fma(_2131, _2131, _2134);
    float _2179 = 1.0 - _2013;
    float _2182 = _2179 * _2179;
    float _2187 = (_2182 * _2182) * _2179;
    float3 _2031 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1920 * _1920) / fast::max(_1906, 9.9999997473787516355514526367188e-05)) * _1939) * _1939)) * _2005;
    float _2276 = _1815 * _2009;
    float _2237 = 12.56637096405029296875 * fast::max(_2013 * _2013, 6.103515625e-05);
    float _2243 = _1780 / (fma(_2276, _2276, _2134) * _2237);
    float3 _2327 = (mix(facet_environment.sample(facet_environmentSmplr, _1262, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1297.xxx, _1297.yyy, float3(params.facet_f0)) * _1316), facet_environment.sample(facet_environmentSmplr, _1262, level(_1398 * (4.0 * (2.0 - _1398)))).xyz, float3(_1393)) + fast::min(fma(((float3(params.facet_f0) + (_1731 * _1728)) * (((_1656 * _1656) * 0.3183098733425140380859375) * (0.5 / fma(_1546, _1697, _1258 * sqrt(fma(_1546 * _1546, _1693, _1687)))))) * _1316, _1572 * _1356, _1572 * ((_1784 * (_1784 * _1778)) * fma(0.039999999105930328369140625, _1373, _1386 * _1728))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1731 * _2187)) * (((_2115 * _2115) * 0.3183098733425140380859375) * (0.5 / fma(_2005, _1697, _1258 * sqrt(fma(_2005 * _2005, _1693, _1687)))))) * _1316, _2031 * _1356, _2031 * ((_2243 * (_2243 * _2237)) * fma(0.039999999105930328369140625, _1373, _1386 * _2187))), float3(65504.0));
    out.fragColor = float4(_2327, 1.0);
    return out;
}

