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
    float3 _948 = fast::normalize(in.v_normal);
    float3 _954 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1261 = fast::max(dot(_948, _954), 9.9999997473787516355514526367188e-05);
    float3 _1265 = reflect(-_954, _948);
    float4 _1300 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1261, params.facet_perceptualRoughness), level(0.0));
    float3 _1319 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1300.y) - 1.0));
    float _1374 = 1.0 - _1261;
    float _1377 = _1374 * _1374;
    float _1384 = fma(0.959999978542327880859375, (_1377 * _1377) * _1374, 0.039999999105930328369140625);
    float _1389 = fast::clamp(params.coat, 0.0, 1.0);
    float _1356 = fma(-_1384, _1389, 1.0);
    float _1394 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1525 = fast::normalize(_954 + frame.lightDirection.xyz);
    float _1459 = fast::clamp(dot(_948, frame.lightDirection.xyz), 0.0, 1.0);
    float _1463 = fast::clamp(dot(_948, _1525), 0.0, 1.0);
    float _1467 = fast::clamp(dot(frame.lightDirection.xyz, _1525), 0.0, 1.0);
    float3 _1563 = cross(_948, _1525);
    float _1566 = _1463 * params.facet_alpha;
    float _1570 = dot(_1563, _1563);
    float _1575 = params.facet_alpha / fma(_1566, _1566, _1570);
    float _1588 = params.facet_alpha * params.facet_alpha;
    float _1594 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1598 = sqrt(fma(_1261 * _1261, _1594, _1588));
    float _1621 = 1.0 - _1467;
    float _1624 = _1621 * _1621;
    float _1629 = (_1624 * _1624) * _1621;
    float3 _1632 = float3(1.0) - float3(params.facet_f0);
    float3 _1485 = frame.lightColor.xyz * _1459;
    float _1666 = _1394 * _1394;
    float _1672 = _1463 * _1666;
    float _1683 = fast::max(_1467 * _1467, 6.103515625e-05);
    float _1686 = 2048.0 * _1666;
    float _1691 = _1686 / (fma(_1672, _1672, _1570) * (_1683 * 25735.927734375));
    float3 _1788 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1791 = dot(_1788, _1788);
    float3 _1796 = _1788 * rsqrt(fast::max(_1791, 9.9999999392252902907785028219223e-09));
    float _1800 = _1791 * float(frame.punctualLights[0].positionFalloff.w);
    float _1805 = fast::clamp(fma(-_1800, _1800, 1.0), 0.0, 1.0);
    float _1824 = fast::clamp(fma(dot(-_1796, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1956 = fast::normalize(_954 + _1796);
    float _1890 = fast::clamp(dot(_948, _1796), 0.0, 1.0);
    float _1894 = fast::clamp(dot(_948, _1956), 0.0, 1.0);
    float _1898 = fast::clamp(dot(_1796, _1956), 0.0, 1.0);
    float3 _1994 = cross(_948, _1956);
    float _1997 = _1894 * params.facet_alpha;
    float _2001 = dot(_1994, _1994);
    float _2006 = params.facet_alpha / fma(_1997, _1997, _2001);
    float _2052 = 1.0 - _1898;
    float _2055 = _2052 * _2052;
    float _2060 = (_2055 * _2055) * _2052;
    float3 _1916 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1805 * _1805) / fast::max(_1791, 9.9999997473787516355514526367188e-05)) * _1824) * _1824)) * _1890;
    float _2103 = _1894 * _1666;
    float _2114 = fast::max(_1898 * _1898, 6.103515625e-05);
    float _2122 = _1686 / (fma(_2103, _2103, _2001) * (_2114 * 25735.927734375));
    float3 _2219 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2222 = dot(_2219, _2219);
    float3 _2227 = _2219 * rsqrt(fast::max(_2222, 9.9999999392252902907785028219223e-09));
    float _2231 = _2222 * float(frame.punctualLights[1].positionFalloff.w);
    float _2236 = fast::clamp(fma(-_2231, _2231, 1.0), 0.0, 1.0);
    float _2255 = fast::clamp(fma(dot(-_2227, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2387 = fast::normalize(_954 + _2227);
    float _2321 = fast::clamp(dot(_948, _2227), 0.0, 1.0);
    float _2325 = fast::clamp(dot(_948, _2387), 0.0, 1.0);
    float _2329 = fast::clamp(dot(_2227, _2387), 0.0, 1.0);
    float3 _2425 = cross(_948, _2387);
    float _2428 = _2325 * params.facet_alpha;
    float _2432 = dot(_2425, _2425);
    float _2437 = params.facet_alpha / fma(_2428, _2428, _2432);
    float _2483 = 1.0 - _2329;
    float _2486 = _2483 * _2483;
    float _2491 = (_2486 * _2486) * _2483;
    float3 _2347 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2236 * _2236) / fast::max(_2222, 9.9999997473787516355514526367188e-05)) * _2255) * _2255)) * _2321;
    float _2534 = _2325 * _1666;
    float _2545 = fast::max(_2329 * _2329, 6.103515625e-05);
    float _2553 = _1686 / (fma(_2534, _2534, _2432) * (_2545 * 25735.927734375));
    float3 _2615 = ((mix(facet_environment.sample(facet_environmentSmplr, _1265, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1300.xxx, _1300.yyy, float3(params.facet_f0)) * _1319), facet_environment.sample(facet_environmentSmplr, _1265, level(_1394 * 4.0)).xyz, float3(_1384 * _1389)) + fast::min(fma(((float3(params.facet_f0) + (_1632 * _1629)) * (((_1575 * _1575) * 0.3183098733425140380859375) * (0.5 / fma(_1459, _1598, _1261 * sqrt(fma(_1459 * _1459, _1594, _1588)))))) * _1319, _1485 * _1356, _1485 * ((_1691 * (_1691 * (12.56637096405029296875 * _1683))) * (fma(0.959999978542327880859375, _1629, 0.039999999105930328369140625) * _1389))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1632 * _2060)) * (((_2006 * _2006) * 0.3183098733425140380859375) * (0.5 / fma(_1890, _1598, _1261 * sqrt(fma(_1890 * _1890, _1594, _1588)))))) * _1319, _1916 * _1356, _1916 * ((_2122 * (_2122 * (12.56637096405029296875 * _2114))) * (fma(0.959999978542327880859375, _2060, 0.039999999105930328369140625) * _1389))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1632 * _2491)) * (((_2437 * _2437) * 0.3183098733425140380859375) * (0.5 / fma(_2321, _1598, _1261 * sqrt(fma(_2321 * _2321, _1594, _1588)))))) * _1319, _2347 * _1356, _2347 * ((_2553 * (_2553 * (12.56637096405029296875 * _2545))) * (fma(0.959999978542327880859375, _2491, 0.039999999105930328369140625) * _1389))), float3(65504.0));
    out.fragColor = float4(_2615, 1.0);
    return out;
}

