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
    float3 _952 = fast::normalize(in.v_normal);
    float3 _958 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1262 = fast::max(dot(_952, _958), 9.9999997473787516355514526367188e-05);
    float3 _1266 = reflect(-_958, _952);
    float4 _1301 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1262, params.facet_perceptualRoughness), level(0.0));
    float3 _1320 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1301.y) - 1.0));
    float _1378 = 1.0 - _1262;
    float _1381 = _1378 * _1378;
    float _1388 = fma(0.959999978542327880859375, (_1381 * _1381) * _1378, 0.039999999105930328369140625);
    float _1393 = fast::clamp(params.coat, 0.0, 1.0);
    float _1360 = fma(-_1388, _1393, 1.0);
    float _1398 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1532 = fast::normalize(_958 + frame.lightDirection.xyz);
    float _1466 = fast::clamp(dot(_952, frame.lightDirection.xyz), 0.0, 1.0);
    float _1470 = fast::clamp(dot(_952, _1532), 0.0, 1.0);
    float _1474 = fast::clamp(dot(frame.lightDirection.xyz, _1532), 0.0, 1.0);
    float3 _1570 = cross(_952, _1532);
    float _1573 = _1470 * params.facet_alpha;
    float _1577 = dot(_1570, _1570);
    float _1582 = params.facet_alpha / fma(_1573, _1573, _1577);
    float _1595 = params.facet_alpha * params.facet_alpha;
    float _1601 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1605 = sqrt(fma(_1262 * _1262, _1601, _1595));
    float _1628 = 1.0 - _1474;
    float _1631 = _1628 * _1628;
    float _1636 = (_1631 * _1631) * _1628;
    float3 _1639 = float3(1.0) - float3(params.facet_f0);
    float3 _1492 = frame.lightColor.xyz * _1466;
    float _1673 = _1398 * _1398;
    float _1679 = _1470 * _1673;
    float _1690 = fast::max(_1474 * _1474, 6.103515625e-05);
    float _1693 = 2048.0 * _1673;
    float _1698 = _1693 / (fma(_1679, _1679, _1577) * (_1690 * 25735.927734375));
    float3 _1795 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1798 = dot(_1795, _1795);
    float3 _1803 = _1795 * rsqrt(fast::max(_1798, 9.9999999392252902907785028219223e-09));
    float _1807 = _1798 * float(frame.punctualLights[0].positionFalloff.w);
    float _1812 = fast::clamp(fma(-_1807, _1807, 1.0), 0.0, 1.0);
    float _1831 = fast::clamp(fma(dot(-_1803, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1963 = fast::normalize(_958 + _1803);
    float _1897 = fast::clamp(dot(_952, _1803), 0.0, 1.0);
    float _1901 = fast::clamp(dot(_952, _1963), 0.0, 1.0);
    float _1905 = fast::clamp(dot(_1803, _1963), 0.0, 1.0);
    float3 _2001 = cross(_952, _1963);
    float _2004 = _1901 * params.facet_alpha;
    float _2008 = dot(_2001, _2001);
    float _2013 = params.facet_alpha / fma(_2004, _2004, _2008);
    float _2059 = 1.0 - _1905;
    float _2062 = _2059 * _2059;
    float _2067 = (_2062 * _2062) * _2059;
    float3 _1923 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1812 * _1812) / fast::max(_1798, 9.9999997473787516355514526367188e-05)) * _1831) * _1831)) * _1897;
    float _2110 = _1901 * _1673;
    float _2121 = fast::max(_1905 * _1905, 6.103515625e-05);
    float _2129 = _1693 / (fma(_2110, _2110, _2008) * (_2121 * 25735.927734375));
    float3 _2226 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2229 = dot(_2226, _2226);
    float3 _2234 = _2226 * rsqrt(fast::max(_2229, 9.9999999392252902907785028219223e-09));
    float _2238 = _2229 * float(frame.punctualLights[1].positionFalloff.w);
    float _2243 = fast::clamp(fma(-_2238, _2238, 1.0), 0.0, 1.0);
    float _2262 = fast::clamp(fma(dot(-_2234, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2394 = fast::normalize(_958 + _2234);
    float _2328 = fast::clamp(dot(_952, _2234), 0.0, 1.0);
    float _2332 = fast::clamp(dot(_952, _2394), 0.0, 1.0);
    float _2336 = fast::clamp(dot(_2234, _2394), 0.0, 1.0);
    float3 _2432 = cross(_952, _2394);
    float _2435 = _2332 * params.facet_alpha;
    float _2439 = dot(_2432, _2432);
    float _2444 = params.facet_alpha / fma(_2435, _2435, _2439);
    float _2490 = 1.0 - _2336;
    float _2493 = _2490 * _2490;
    float _2498 = (_2493 * _2493) * _2490;
    float3 _2354 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2243 * _2243) / fast::max(_2229, 9.9999997473787516355514526367188e-05)) * _2262) * _2262)) * _2328;
    float _2541 = _2332 * _1673;
    float _2552 = fast::max(_2336 * _2336, 6.103515625e-05);
    float _2560 = _1693 / (fma(_2541, _2541, _2439) * (_2552 * 25735.927734375));
    float3 _2622 = ((mix(facet_environment.sample(facet_environmentSmplr, _1266, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1301.xxx, _1301.yyy, float3(params.facet_f0)) * _1320), facet_environment.sample(facet_environmentSmplr, _1266, level(_1398 * (4.0 * (2.0 - _1398)))).xyz, float3(_1388 * _1393)) + fast::min(fma(((float3(params.facet_f0) + (_1639 * _1636)) * (((_1582 * _1582) * 0.3183098733425140380859375) * (0.5 / fma(_1466, _1605, _1262 * sqrt(fma(_1466 * _1466, _1601, _1595)))))) * _1320, _1492 * _1360, _1492 * ((_1698 * (_1698 * (12.56637096405029296875 * _1690))) * (fma(0.959999978542327880859375, _1636, 0.039999999105930328369140625) * _1393))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1639 * _2067)) * (((_2013 * _2013) * 0.3183098733425140380859375) * (0.5 / fma(_1897, _1605, _1262 * sqrt(fma(_1897 * _1897, _1601, _1595)))))) * _1320, _1923 * _1360, _1923 * ((_2129 * (_2129 * (12.56637096405029296875 * _2121))) * (fma(0.959999978542327880859375, _2067, 0.039999999105930328369140625) * _1393))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1639 * _2498)) * (((_2444 * _2444) * 0.3183098733425140380859375) * (0.5 / fma(_2328, _1605, _1262 * sqrt(fma(_2328 * _2328, _1601, _1595)))))) * _1320, _2354 * _1360, _2354 * ((_2560 * (_2560 * (12.56637096405029296875 * _2552))) * (fma(0.959999978542327880859375, _2498, 0.039999999105930328369140625) * _1393))), float3(65504.0));
    out.fragColor = float4(_2622, 1.0);
    return out;
}

