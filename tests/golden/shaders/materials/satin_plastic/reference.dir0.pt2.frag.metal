#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    float3 _959 = fast::normalize(in.v_normal);
    float3 _965 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1111 = _959.y;
    float _1116 = _959.z;
    float _1121 = _959.x;
    float _1239 = fast::max(dot(_959, _965), 9.9999997473787516355514526367188e-05);
    float3 _1243 = reflect(-_965, _959);
    float4 _1278 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1239, params.facet_perceptualRoughness), level(0.0));
    float3 _1297 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1278.y) - 1.0));
    float _1386 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1343 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1239, _1386), level(0.0));
    float3 _1393 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1356 = _1343.z;
    float _1358 = fma(-fast::max(_1393.x, fast::max(_1393.y, _1393.z)), _1356, 1.0);
    float _1402 = _1386 * _1386;
    float _1363 = _1343.w;
    float3 _1379 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1111)) + (frame.sh[2].xyz * _1116)) + (frame.sh[3].xyz * _1121)) + (((((frame.sh[4].xyz * (_1121 * _1111)) + (frame.sh[5].xyz * (_1111 * _1116))) + (frame.sh[6].xyz * fma(3.0 * _1116, _1116, -1.0))) + (frame.sh[7].xyz * (_1121 * _1116))) + (frame.sh[8].xyz * fma(_1121, _1121, -(_1111 * _1111)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1243, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1278.xxx, _1278.yyy, float3(params.facet_f0)) * _1297)) * _1358;
    float3 _1455 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1458 = dot(_1455, _1455);
    float3 _1463 = _1455 * rsqrt(fast::max(_1458, 9.9999999392252902907785028219223e-09));
    float _1467 = _1458 * float(frame.punctualLights[0].positionFalloff.w);
    float _1472 = fast::clamp(fma(-_1467, _1467, 1.0), 0.0, 1.0);
    float _1491 = fast::clamp(fma(dot(-_1463, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1500 = float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1472 * _1472) / fast::max(_1458, 9.9999997473787516355514526367188e-05)) * _1491) * _1491);
    float3 _1623 = fast::normalize(_965 + _1463);
    float _1556 = fast::clamp(dot(_959, _1463), 0.0, 1.0);
    float _1560 = fast::clamp(dot(_959, _1623), 0.0, 1.0);
    float3 _1661 = cross(_959, _1623);
    float _1664 = _1560 * params.facet_alpha;
    float _1673 = params.facet_alpha / fma(_1664, _1664, dot(_1661, _1661));
    float _1686 = params.facet_alpha * params.facet_alpha;
    float _1692 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1696 = sqrt(fma(_1239 * _1239, _1692, _1686));
    float _1719 = 1.0 - fast::clamp(dot(_1463, _1623), 0.0, 1.0);
    float _1722 = _1719 * _1719;
    float3 _1730 = float3(1.0) - float3(params.facet_f0);
    float _1763 = 8192.0 * fma(-_1556, _1239, _1556 + _1239);
    float _1767 = 1.0 / (_1402 * _1763);
    float _1774 = 2048.0 * _1402;
    float3 _1597 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1837 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1840 = dot(_1837, _1837);
    float3 _1845 = _1837 * rsqrt(fast::max(_1840, 9.9999999392252902907785028219223e-09));
    float _1849 = _1840 * float(frame.punctualLights[1].positionFalloff.w);
    float _1854 = fast::clamp(fma(-_1849, _1849, 1.0), 0.0, 1.0);
    float _1873 = fast::clamp(fma(dot(-_1845, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1882 = float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1854 * _1854) / fast::max(_1840, 9.9999997473787516355514526367188e-05)) * _1873) * _1873);
    float3 _2005 = fast::normalize(_965 + _1845);
    float _1938 = fast::clamp(dot(_959, _1845), 0.0, 1.0);
    float _1942 = fast::clamp(dot(_959, _2005), 0.0, 1.0);
    float3 _2043 = cross(_959, _2005);
    float _2046 = _1942 * params.facet_alpha;
    float _2055 = params.facet_alpha / fma(_2046, _2046, dot(_2043, _2043));
    float _2101 = 1.0 - fast::clamp(dot(_1845, _2005), 0.0, 1.0);
    float _2104 = _2101 * _2101;
    float _2145 = 8192.0 * fma(-_1938, _1239, _1938 + _1239);
    float _2149 = 1.0 / (_1402 * _2145);
    float3 _2184 = (fma(facet_environment.sample(facet_environmentSmplr, _1243, level(_1386 * (4.0 * (2.0 - _1386)))).xyz, _1393 * _1356, _1379) + fast::min(fma(fma((float3(params.facet_f0) + (_1730 * ((_1722 * _1722) * _1719))) * (((_1673 * _1673) * 0.3183098733425140380859375) * (0.5 / fma(_1556, _1696, _1239 * sqrt(fma(_1556 * _1556, _1692, _1686))))), _1297, _1597), (_1500 * _1556) * _1358, (_1393 * ((((fma(_1767, _1763, 2.0) * pow(fast::max(fma(-_1560, _1560, 1.0), 0.0), 0.5 * (_1767 * _1763))) * 0.15915493667125701904296875) * (_1556 * (_1767 * _1774))) * _1363)) * _1500), float3(65504.0))) + fast::min(fma(fma((float3(params.facet_f0) + (_1730 * ((_2104 * _2104) * _2101))) * (((_2055 * _2055) * 0.3183098733425140380859375) * (0.5 / fma(_1938, _1696, _1239 * sqrt(fma(_1938 * _1938, _1692, _1686))))), _1297, _1597), (_1882 * _1938) * _1358, (_1393 * ((((fma(_2149, _2145, 2.0) * pow(fast::max(fma(-_1942, _1942, 1.0), 0.0), 0.5 * (_2149 * _2145))) * 0.15915493667125701904296875) * (_1938 * (_2149 * _1774))) * _1363)) * _1882), float3(65504.0));
    out.fragColor = float4(_2184, 1.0);
    return out;
}

