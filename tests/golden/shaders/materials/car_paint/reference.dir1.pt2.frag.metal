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
    float _1258 = fast::max(dot(_948, _954), 9.9999997473787516355514526367188e-05);
    float3 _1262 = reflect(-_954, _948);
    float4 _1297 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1258, params.facet_perceptualRoughness), level(0.0));
    float3 _1316 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1297.y) - 1.0));
    float _1371 = 1.0 - _1258;
    float _1374 = _1371 * _1371;
    float _1381 = fma(0.959999978542327880859375, (_1374 * _1374) * _1371, 0.039999999105930328369140625);
    float _1386 = fast::clamp(params.coat, 0.0, 1.0);
    float _1353 = fma(-_1381, _1386, 1.0);
    float _1391 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1522 = fast::normalize(_954 + frame.lightDirection.xyz);
    float _1456 = fast::clamp(dot(_948, frame.lightDirection.xyz), 0.0, 1.0);
    float _1460 = fast::clamp(dot(_948, _1522), 0.0, 1.0);
    float _1464 = fast::clamp(dot(frame.lightDirection.xyz, _1522), 0.0, 1.0);
    float3 _1560 = cross(_948, _1522);
    float _1563 = _1460 * params.facet_alpha;
    float _1567 = dot(_1560, _1560);
    float _1572 = params.facet_alpha / fma(_1563, _1563, _1567);
    float _1585 = params.facet_alpha * params.facet_alpha;
    float _1591 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1595 = sqrt(fma(_1258 * _1258, _1591, _1585));
    float _1618 = 1.0 - _1464;
    float _1621 = _1618 * _1618;
    float _1626 = (_1621 * _1621) * _1618;
    float3 _1629 = float3(1.0) - float3(params.facet_f0);
    float3 _1482 = frame.lightColor.xyz * _1456;
    float _1663 = _1391 * _1391;
    float _1669 = _1460 * _1663;
    float _1680 = fast::max(_1464 * _1464, 6.103515625e-05);
    float _1683 = 2048.0 * _1663;
    float _1688 = _1683 / (fma(_1669, _1669, _1567) * (_1680 * 25735.927734375));
    float3 _1785 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1788 = dot(_1785, _1785);
    float3 _1793 = _1785 * rsqrt(fast::max(_1788, 9.9999999392252902907785028219223e-09));
    float _1797 = _1788 * float(frame.punctualLights[0].positionFalloff.w);
    float _1802 = fast::clamp(fma(-_1797, _1797, 1.0), 0.0, 1.0);
    float _1821 = fast::clamp(fma(dot(-_1793, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1953 = fast::normalize(_954 + _1793);
    float _1887 = fast::clamp(dot(_948, _1793), 0.0, 1.0);
    float _1891 = fast::clamp(dot(_948, _1953), 0.0, 1.0);
    float _1895 = fast::clamp(dot(_1793, _1953), 0.0, 1.0);
    float3 _1991 = cross(_948, _1953);
    float _1994 = _1891 * params.facet_alpha;
    float _1998 = dot(_1991, _1991);
    float _2003 = params.facet_alpha / fma(_1994, _1994, _1998);
    float _2049 = 1.0 - _1895;
    float _2052 = _2049 * _2049;
    float _2057 = (_2052 * _2052) * _2049;
    float3 _1913 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1802 * _1802) / fast::max(_1788, 9.9999997473787516355514526367188e-05)) * _1821) * _1821)) * _1887;
    float _2100 = _1891 * _1663;
    float _2111 = fast::max(_1895 * _1895, 6.103515625e-05);
    float _2119 = _1683 / (fma(_2100, _2100, _1998) * (_2111 * 25735.927734375));
    float3 _2216 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2219 = dot(_2216, _2216);
    float3 _2224 = _2216 * rsqrt(fast::max(_2219, 9.9999999392252902907785028219223e-09));
    float _2228 = _2219 * float(frame.punctualLights[1].positionFalloff.w);
    float _2233 = fast::clamp(fma(-_2228, _2228, 1.0), 0.0, 1.0);
    float _2252 = fast::clamp(fma(dot(-_2224, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2384 = fast::normalize(_954 + _2224);
    float _2318 = fast::clamp(dot(_948, _2224), 0.0, 1.0);
    float _2322 = fast::clamp(dot(_948, _2384), 0.0, 1.0);
    float _2326 = fast::clamp(dot(_2224, _2384), 0.0, 1.0);
    float3 _2422 = cross(_948, _2384);
    float _2425 = _2322 * params.facet_alpha;
    float _2429 = dot(_2422, _2422);
    float _2434 = params.facet_alpha / fma(_2425, _2425, _2429);
    float _2480 = 1.0 - _2326;
    float _2483 = _2480 * _2480;
    float _2488 = (_2483 * _2483) * _2480;
    float3 _2344 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2233 * _2233) / fast::max(_2219, 9.9999997473787516355514526367188e-05)) * _2252) * _2252)) * _2318;
    float _2531 = _2322 * _1663;
    float _2542 = fast::max(_2326 * _2326, 6.103515625e-05);
    float _2550 = _1683 / (fma(_2531, _2531, _2429) * (_2542 * 25735.927734375));
    float3 _2612 = ((mix(facet_environment.sample(facet_environmentSmplr, _1262, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1297.xxx, _1297.yyy, float3(params.facet_f0)) * _1316), facet_environment.sample(facet_environmentSmplr, _1262, level(_1391 * 4.0)).xyz, float3(_1381 * _1386)) + fast::min(fma(((float3(params.facet_f0) + (_1629 * _1626)) * (((_1572 * _1572) * 0.3183098733425140380859375) * (0.5 / fma(_1456, _1595, _1258 * sqrt(fma(_1456 * _1456, _1591, _1585)))))) * _1316, _1482 * _1353, _1482 * ((_1688 * (_1688 * (12.56637096405029296875 * _1680))) * (fma(0.959999978542327880859375, _1626, 0.039999999105930328369140625) * _1386))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1629 * _2057)) * (((_2003 * _2003) * 0.3183098733425140380859375) * (0.5 / fma(_1887, _1595, _1258 * sqrt(fma(_1887 * _1887, _1591, _1585)))))) * _1316, _1913 * _1353, _1913 * ((_2119 * (_2119 * (12.56637096405029296875 * _2111))) * (fma(0.959999978542327880859375, _2057, 0.039999999105930328369140625) * _1386))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1629 * _2488)) * (((_2434 * _2434) * 0.3183098733425140380859375) * (0.5 / fma(_2318, _1595, _1258 * sqrt(fma(_2318 * _2318, _1591, _1585)))))) * _1316, _2344 * _1353, _2344 * ((_2550 * (_2550 * (12.56637096405029296875 * _2542))) * (fma(0.959999978542327880859375, _2488, 0.039999999105930328369140625) * _1386))), float3(65504.0));
    out.fragColor = float4(_2612, 1.0);
    return out;
}

