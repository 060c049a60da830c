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
    float _1388 = 1.0 - _1272;
    float _1391 = _1388 * _1388;
    float _1398 = fma(0.959999978542327880859375, (_1391 * _1391) * _1388, 0.039999999105930328369140625);
    float _1403 = fast::clamp(params.coat, 0.0, 1.0);
    float _1370 = fma(-_1398, _1403, 1.0);
    float _1408 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1542 = fast::normalize(_968 + frame.lightDirection.xyz);
    float _1476 = fast::clamp(dot(_962, frame.lightDirection.xyz), 0.0, 1.0);
    float _1480 = fast::clamp(dot(_962, _1542), 0.0, 1.0);
    float _1484 = fast::clamp(dot(frame.lightDirection.xyz, _1542), 0.0, 1.0);
    float _1580 = 4096.0 * params.facet_alpha;
    float3 _1596 = cross(_962, _1542);
    float _1600 = _1596.x;
    float4 _1604 = float4(_1600, _1596.yz, params.facet_alpha * _1480) * 64.0;
    float _1586 = _1580 / dot(_1604, _1604);
    float _1615 = params.facet_alpha * params.facet_alpha;
    float _1621 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1625 = sqrt(fma(_1272 * _1272, _1621, _1615));
    float _1648 = 1.0 - _1484;
    float _1651 = _1648 * _1648;
    float _1656 = (_1651 * _1651) * _1648;
    float3 _1659 = float3(1.0) - float3(params.facet_f0);
    float3 _1502 = frame.lightColor.xyz * _1476;
    float _1695 = _1408 * _1408;
    float4 _1747 = float4(_1600, _1596.yz, _1695 * _1480) * 64.0;
    float _1705 = 12.56637096405029296875 * fast::max(_1484 * _1484, 6.103515625e-05);
    float _1707 = 4096.0 * _1695;
    float _1711 = _1707 / (dot(_1747, _1747) * _1705);
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
    float3 _2047 = cross(_962, _1993);
    float _2051 = _2047.x;
    float4 _2055 = float4(_2051, _2047.yz, params.facet_alpha * _1931) * 64.0;
    float _2037 = _1580 / dot(_2055, _2055);
    float _2099 = 1.0 - _1935;
    float _2102 = _2099 * _2099;
    float _2107 = (_2102 * _2102) * _2099;
    float3 _1953 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1842 * _1842) / fast::max(_1828, 9.9999997473787516355514526367188e-05)) * _1861) * _1861)) * _1927;
    float4 _2198 = float4(_2051, _2047.yz, _1695 * _1931) * 64.0;
    float _2156 = 12.56637096405029296875 * fast::max(_1935 * _1935, 6.103515625e-05);
    float _2162 = _1707 / (dot(_2198, _2198) * _2156);
    float3 _2276 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2279 = dot(_2276, _2276);
    float3 _2284 = _2276 * rsqrt(fast::max(_2279, 9.9999999392252902907785028219223e-09));
    float _2288 = _2279 * float(frame.punctualLights[1].positionFalloff.w);
    float _2293 = fast::clamp(fma(-_2288, _2288, 1.0), 0.0, 1.0);
    float _2312 = fast::clamp(fma(dot(-_2284, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2444 = fast::normalize(_968 + _2284);
    float _2378 = fast::clamp(dot(_962, _2284), 0.0, 1.0);
    float _2382 = fast::clamp(dot(_962, _2444), 0.0, 1.0);
    float _2386 = fast::clamp(dot(_2284, _2444), 0.0, 1.0);
    float3 _2498 = cross(_962, _2444);
    float _2502 = _2498.x;
    float4 _2506 = float4(_2502, _2498.yz, params.facet_alpha * _2382) * 64.0;
    float _2488 = _1580 / dot(_2506, _2506);
    float _2550 = 1.0 - _2386;
    float _2553 = _2550 * _2550;
    float _2558 = (_2553 * _2553) * _2550;
    float3 _2404 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2293 * _2293) / fast::max(_2279, 9.9999997473787516355514526367188e-05)) * _2312) * _2312)) * _2378;
    float4 _2649 = float4(_2502, _2498.yz, _1695 * _2382) * 64.0;
    float _2607 = 12.56637096405029296875 * fast::max(_2386 * _2386, 6.103515625e-05);
    float _2613 = _1707 / (dot(_2649, _2649) * _2607);
    float3 _2692 = ((mix(facet_environment.sample(facet_environmentSmplr, _1276, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1311.xxx, _1311.yyy, float3(params.facet_f0)) * _1330), facet_environment.sample(facet_environmentSmplr, _1276, level(_1408 * (4.0 * (2.0 - _1408)))).xyz, float3(_1398 * _1403)) + fast::min(fma(((float3(params.facet_f0) + (_1659 * _1656)) * (((_1586 * _1586) * 0.3183098733425140380859375) * (0.5 / fma(_1476, _1625, _1272 * sqrt(fma(_1476 * _1476, _1621, _1615)))))) * _1330, _1502 * _1370, _1502 * ((_1711 * (_1711 * _1705)) * (fma(0.959999978542327880859375, _1656, 0.039999999105930328369140625) * _1403))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1659 * _2107)) * (((_2037 * _2037) * 0.3183098733425140380859375) * (0.5 / fma(_1927, _1625, _1272 * sqrt(fma(_1927 * _1927, _1621, _1615)))))) * _1330, _1953 * _1370, _1953 * ((_2162 * (_2162 * _2156)) * (fma(0.959999978542327880859375, _2107, 0.039999999105930328369140625) * _1403))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1659 * _2558)) * (((_2488 * _2488) * 0.3183098733425140380859375) * (0.5 / fma(_2378, _1625, _1272 * sqrt(fma(_2378 * _2378, _1621, _1615)))))) * _1330, _2404 * _1370, _2404 * ((_2613 * (_2613 * _2607)) * (fma(0.959999978542327880859375, _2558, 0.039999999105930328369140625) * _1403))), float3(65504.0));
    out.fragColor = float4(_2692, 1.0);
    return out;
}

