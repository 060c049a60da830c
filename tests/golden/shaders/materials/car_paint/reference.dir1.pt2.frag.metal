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
    float3 _950 = fast::normalize(in.v_normal);
    float3 _956 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1260 = fast::max(dot(_950, _956), 9.9999997473787516355514526367188e-05);
    float3 _1264 = reflect(-_956, _950);
    float4 _1299 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1260, params.facet_perceptualRoughness), level(0.0));
    float3 _1318 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1299.y) - 1.0));
    float _1373 = 1.0 - _1260;
    float _1376 = _1373 * _1373;
    float _1383 = fma(0.959999978542327880859375, (_1376 * _1376) * _1373, 0.039999999105930328369140625);
    float _1388 = fast::clamp(params.coat, 0.0, 1.0);
    float _1355 = fma(-_1383, _1388, 1.0);
    float _1393 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1524 = fast::normalize(_956 + frame.lightDirection.xyz);
    float _1458 = fast::clamp(dot(_950, frame.lightDirection.xyz), 0.0, 1.0);
    float _1462 = fast::clamp(dot(_950, _1524), 0.0, 1.0);
    float _1466 = fast::clamp(dot(frame.lightDirection.xyz, _1524), 0.0, 1.0);
    float3 _1562 = cross(_950, _1524);
    float _1565 = _1462 * params.facet_alpha;
    float _1574 = params.facet_alpha / fma(_1565, _1565, dot(_1562, _1562));
    float _1587 = params.facet_alpha * params.facet_alpha;
    float _1593 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1597 = sqrt(fma(_1260 * _1260, _1593, _1587));
    float _1620 = 1.0 - _1466;
    float _1623 = _1620 * _1620;
    float _1628 = (_1623 * _1623) * _1620;
    float3 _1631 = float3(1.0) - float3(params.facet_f0);
    float3 _1484 = frame.lightColor.xyz * _1458;
    float _1665 = _1393 * _1393;
    float3 _1669 = _1562 * 64.0;
    float _1672 = 64.0 * _1665;
    float _1673 = _1462 * _1672;
    float _1685 = 12.56637096405029296875 * fast::max(_1466 * _1466, 6.103515625e-05);
    float _1687 = 4096.0 * _1665;
    float _1691 = _1687 / (fma(_1673, _1673, dot(_1669, _1669)) * _1685);
    float3 _1788 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1791 = dot(_1788, _1788);
    float3 _1796 = _1788 * rsqrt(fast::max(_1791, 9.9999999392252902907785028219223e-09));
    float _1800 = _1791 * float(frame.punctualLights[0].positionFalloff.w);
    float _1805 = fast::clamp(fma(-_1800, _1800, 1.0), 0.0, 1.0);
    float _1824 = fast::clamp(fma(dot(-_1796, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1956 = fast::normalize(_956 + _1796);
    float _1890 = fast::clamp(dot(_950, _1796), 0.0, 1.0);
    float _1894 = fast::clamp(dot(_950, _1956), 0.0, 1.0);
    float _1898 = fast::clamp(dot(_1796, _1956), 0.0, 1.0);
    float3 _1994 = cross(_950, _1956);
    float _1997 = _1894 * params.facet_alpha;
    float _2006 = params.facet_alpha / fma(_1997, _1997, dot(_1994, _1994));
    float _2052 = 1.0 - _1898;
    float _2055 = _2052 * _2052;
    float _2060 = (_2055 * _2055) * _2052;
    float3 _1916 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1805 * _1805) / fast::max(_1791, 9.9999997473787516355514526367188e-05)) * _1824) * _1824)) * _1890;
    float3 _2101 = _1994 * 64.0;
    float _2105 = _1894 * _1672;
    float _2117 = 12.56637096405029296875 * fast::max(_1898 * _1898, 6.103515625e-05);
    float _2123 = _1687 / (fma(_2105, _2105, dot(_2101, _2101)) * _2117);
    float3 _2220 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2223 = dot(_2220, _2220);
    float3 _2228 = _2220 * rsqrt(fast::max(_2223, 9.9999999392252902907785028219223e-09));
    float _2232 = _2223 * float(frame.punctualLights[1].positionFalloff.w);
    float _2237 = fast::clamp(fma(-_2232, _2232, 1.0), 0.0, 1.0);
    float _2256 = fast::clamp(fma(dot(-_2228, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2388 = fast::normalize(_956 + _2228);
    float _2322 = fast::clamp(dot(_950, _2228), 0.0, 1.0);
    float _2326 = fast::clamp(dot(_950, _2388), 0.0, 1.0);
    float _2330 = fast::clamp(dot(_2228, _2388), 0.0, 1.0);
    float3 _2426 = cross(_950, _2388);
    float _2429 = _2326 * params.facet_alpha;
    float _2438 = params.facet_alpha / fma(_2429, _2429, dot(_2426, _2426));
    float _2484 = 1.0 - _2330;
    float _2487 = _2484 * _2484;
    float _2492 = (_2487 * _2487) * _2484;
    float3 _2348 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2237 * _2237) / fast::max(_2223, 9.9999997473787516355514526367188e-05)) * _2256) * _2256)) * _2322;
    float3 _2533 = _2426 * 64.0;
    float _2537 = _2326 * _1672;
    float _2549 = 12.56637096405029296875 * fast::max(_2330 * _2330, 6.103515625e-05);
    float _2555 = _1687 / (fma(_2537, _2537, dot(_2533, _2533)) * _2549);
    float3 _2617 = ((mix(facet_environment.sample(facet_environmentSmplr, _1264, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1299.xxx, _1299.yyy, float3(params.facet_f0)) * _1318), facet_environment.sample(facet_environmentSmplr, _1264, level(_1393 * 4.0)).xyz, float3(_1383 * _1388)) + fast::min(fma(((float3(params.facet_f0) + (_1631 * _1628)) * (((_1574 * _1574) * 0.3183098733425140380859375) * (0.5 / fma(_1458, _1597, _1260 * sqrt(fma(_1458 * _1458, _1593, _1587)))))) * _1318, _1484 * _1355, _1484 * ((_1691 * (_1691 * _1685)) * (fma(0.959999978542327880859375, _1628, 0.039999999105930328369140625) * _1388))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1631 * _2060)) * (((_2006 * _2006) * 0.3183098733425140380859375) * (0.5 / fma(_1890, _1597, _1260 * sqrt(fma(_1890 * _1890, _1593, _1587)))))) * _1318, _1916 * _1355, _1916 * ((_2123 * (_2123 * _2117)) * (fma(0.959999978542327880859375, _2060, 0.039999999105930328369140625) * _1388))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1631 * _2492)) * (((_2438 * _2438) * 0.3183098733425140380859375) * (0.5 / fma(_2322, _1597, _1260 * sqrt(fma(_2322 * _2322, _1593, _1587)))))) * _1318, _2348 * _1355, _2348 * ((_2555 * (_2555 * _2549)) * (fma(0.959999978542327880859375, _2492, 0.039999999105930328369140625) * _1388))), float3(65504.0));
    out.fragColor = float4(_2617, 1.0);
    return out;
}

