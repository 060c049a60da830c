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
    float3 _959 = fast::normalize(in.v_normal);
    float3 _965 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1270 = fast::max(dot(_959, _965), 9.9999997473787516355514526367188e-05);
    float3 _1274 = reflect(-_965, _959);
    float4 _1309 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1270, params.facet_perceptualRoughness), level(0.0));
    float3 _1328 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1309.y) - 1.0));
    float _1385 = 1.0 - _1270;
    float _1388 = _1385 * _1385;
    float _1395 = fma(0.959999978542327880859375, (_1388 * _1388) * _1385, 0.039999999105930328369140625);
    float _1365 = fma(-_1395, params.facet_clearCoat, 1.0);
    float3 _1522 = fast::normalize(_965 + frame.lightDirection.xyz);
    float _1455 = fast::clamp(dot(_959, frame.lightDirection.xyz), 0.0, 1.0);
    float _1459 = fast::clamp(dot(_959, _1522), 0.0, 1.0);
    float _1463 = fast::clamp(dot(frame.lightDirection.xyz, _1522), 0.0, 1.0);
    float _1560 = 4096.0 * params.facet_alpha;
    float3 _1578 = cross(_959, _1522) * 64.0;
    float _1580 = 64.0 * params.facet_alpha;
    float _1582 = _1580 * _1459;
    float _1585 = dot(_1578, _1578);
    float _1566 = _1560 / fma(_1582, _1582, _1585);
    float _1597 = params.facet_alpha * params.facet_alpha;
    float _1603 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1607 = sqrt(fma(_1270 * _1270, _1603, _1597));
    float _1630 = 1.0 - _1463;
    float _1633 = _1630 * _1630;
    float _1638 = (_1633 * _1633) * _1630;
    float3 _1641 = float3(1.0) - float3(params.facet_f0);
    float _1724 = 64.0 * params.facet_clearCoatAlpha;
    float _1726 = _1724 * _1459;
    float _1679 = 12.56637096405029296875 * fast::max(_1463 * _1463, 6.103515625e-05);
    float _1681 = 4096.0 * params.facet_clearCoatAlpha;
    float _1685 = _1681 / (fma(_1726, _1726, _1585) * _1679);
    float _1702 = 0.959999978542327880859375 * params.facet_clearCoat;
    float3 _1791 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1794 = dot(_1791, _1791);
    float3 _1799 = _1791 * rsqrt(fast::max(_1794, 9.9999999392252902907785028219223e-09));
    float _1803 = _1794 * float(frame.punctualLights[0].positionFalloff.w);
    float _1808 = fast::clamp(fma(-_1803, _1803, 1.0), 0.0, 1.0);
    float _1827 = fast::clamp(fma(dot(-_1799, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1959 = fast::normalize(_965 + _1799);
    float _1892 = fast::clamp(dot(_959, _1799), 0.0, 1.0);
    float _1896 = fast::clamp(dot(_959, _1959), 0.0, 1.0);
    float _1900 = fast::clamp(dot(_1799, _1959), 0.0, 1.0);
    float3 _2015 = cross(_959, _1959) * 64.0;
    float _2019 = _1580 * _1896;
    float _2022 = dot(_2015, _2015);
    float _2003 = _1560 / fma(_2019, _2019, _2022);
    float _2067 = 1.0 - _1900;
    float _2070 = _2067 * _2067;
    float _2075 = (_2070 * _2070) * _2067;
    float _2163 = _1724 * _1896;
    float _2116 = 12.56637096405029296875 * fast::max(_1900 * _1900, 6.103515625e-05);
    float _2122 = _1681 / (fma(_2163, _2163, _2022) * _2116);
    float3 _2193 = (mix(facet_environment.sample(facet_environmentSmplr, _1274, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1309.xxx, _1309.yyy, float3(params.facet_f0)) * _1328), facet_environment.sample(facet_environmentSmplr, _1274, level(params.facet_clearCoatLod)).xyz, float3(_1395 * params.facet_clearCoat)) + fast::min(fast::min(((((float3(params.facet_f0) + (_1641 * _1638)) * (((_1566 * _1566) * 0.3183098733425140380859375) * (0.5 / fma(_1455, _1607, _1270 * sqrt(fma(_1455 * _1455, _1603, _1597)))))) * _1328) * _1365) + float3((_1685 * (_1685 * _1679)) * fma(0.039999999105930328369140625, params.facet_clearCoat, _1702 * _1638)), float3(65504.0)) * (frame.lightColor.xyz * _1455), float3(65504.0))) + fast::min(fast::min(((((float3(params.facet_f0) + (_1641 * _2075)) * (((_2003 * _2003) * 0.3183098733425140380859375) * (0.5 / fma(_1892, _1607, _1270 * sqrt(fma(_1892 * _1892, _1603, _1597)))))) * _1328) * _1365) + float3((_2122 * (_2122 * _2116)) * fma(0.039999999105930328369140625, params.facet_clearCoat, _1702 * _2075)), float3(65504.0)) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1808 * _1808) / fast::max(_1794, 9.9999997473787516355514526367188e-05)) * _1827) * _1827)) * _1892), float3(65504.0));
    float3 _2228 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2231 = dot(_2228, _2228);
    float3 _2236 = _2228 * rsqrt(fast::max(_2231, 9.9999999392252902907785028219223e-09));
    float _2240 = _2231 * float(frame.punctualLights[1].positionFalloff.w);
    float _2245 = fast::clamp(fma(-_2240, _2240, 1.0), 0.0, 1.0);
    float _2264 = fast::clamp(fma(dot(-_2236, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2396 = fast::normalize(_965 + _2236);
    float _2329 = fast::clamp(dot(_959, _2236), 0.0, 1.0);
    float _2333 = fast::clamp(dot(_959, _2396), 0.0, 1.0);
    float _2337 = fast::clamp(dot(_2236, _2396), 0.0, 1.0);
    float3 _2452 = cross(_959, _2396) * 64.0;
    float _2456 = _1580 * _2333;
    float _2459 = dot(_2452, _2452);
    float _2440 = _1560 / fma(_2456, _2456, _2459);
    float _2504 = 1.0 - _2337;
    float _2507 = _2504 * _2504;
    float _2512 = (_2507 * _2507) * _2504;
    float _2600 = _1724 * _2333;
    float _2553 = 12.56637096405029296875 * fast::max(_2337 * _2337, 6.103515625e-05);
    float _2559 = _1681 / (fma(_2600, _2600, _2459) * _2553);
    out.fragColor = float4(_2193 + fast::min(fast::min(((((float3(params.facet_f0) + (_1641 * _2512)) * (((_2440 * _2440) * 0.3183098733425140380859375) * (0.5 / fma(_2329, _1607, _1270 * sqrt(fma(_2329 * _2329, _1603, _1597)))))) * _1328) * _1365) + float3((_2559 * (_2559 * _2553)) * fma(0.039999999105930328369140625, params.facet_clearCoat, _1702 * _2512)), float3(65504.0)) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2245 * _2245) / fast::max(_2231, 9.9999997473787516355514526367188e-05)) * _2264) * _2264)) * _2329), float3(65504.0)), 1.0);
    return out;
}

