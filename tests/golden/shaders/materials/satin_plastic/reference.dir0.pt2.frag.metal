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
    float3 _954 = fast::normalize(in.v_normal);
    float3 _960 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1106 = _954.y;
    float _1111 = _954.z;
    float _1116 = _954.x;
    float _1234 = fast::max(dot(_954, _960), 9.9999997473787516355514526367188e-05);
    float3 _1238 = reflect(-_960, _954);
    float4 _1273 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1234, params.facet_perceptualRoughness), level(0.0));
    float3 _1292 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1273.y) - 1.0));
    float _1376 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1333 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1234, _1376), level(0.0));
    float3 _1383 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1346 = _1333.z;
    float _1348 = fma(-fast::max(_1383.x, fast::max(_1383.y, _1383.z)), _1346, 1.0);
    float _1392 = _1376 * _1376;
    float _1353 = _1333.w;
    float3 _1369 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1106)) + (frame.sh[2].xyz * _1111)) + (frame.sh[3].xyz * _1116)) + (((((frame.sh[4].xyz * (_1116 * _1106)) + (frame.sh[5].xyz * (_1106 * _1111))) + (frame.sh[6].xyz * fma(3.0 * _1111, _1111, -1.0))) + (frame.sh[7].xyz * (_1116 * _1111))) + (frame.sh[8].xyz * fma(_1116, _1116, -(_1106 * _1106)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1238, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1273.xxx, _1273.yyy, float3(params.facet_f0)) * _1292)) * _1348;
    float3 _1440 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1443 = dot(_1440, _1440);
    float3 _1448 = _1440 * rsqrt(fast::max(_1443, 9.9999999392252902907785028219223e-09));
    float _1452 = _1443 * float(frame.punctualLights[0].positionFalloff.w);
    float _1457 = fast::clamp(fma(-_1452, _1452, 1.0), 0.0, 1.0);
    float _1476 = fast::clamp(fma(dot(-_1448, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1485 = float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1457 * _1457) / fast::max(_1443, 9.9999997473787516355514526367188e-05)) * _1476) * _1476);
    float3 _1608 = fast::normalize(_960 + _1448);
    float _1541 = fast::clamp(dot(_954, _1448), 0.0, 1.0);
    float _1545 = fast::clamp(dot(_954, _1608), 0.0, 1.0);
    float3 _1646 = cross(_954, _1608);
    float _1649 = _1545 * params.facet_alpha;
    float _1658 = params.facet_alpha / fma(_1649, _1649, dot(_1646, _1646));
    float _1671 = params.facet_alpha * params.facet_alpha;
    float _1677 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1681 = sqrt(fma(_1234 * _1234, _1677, _1671));
    float _1704 = 1.0 - fast::clamp(dot(_1448, _1608), 0.0, 1.0);
    float _1707 = _1704 * _1704;
    float3 _1715 = float3(1.0) - float3(params.facet_f0);
    float _1748 = 8192.0 * fma(-_1541, _1234, _1541 + _1234);
    float _1752 = 1.0 / (_1392 * _1748);
    float _1759 = 2048.0 * _1392;
    float3 _1582 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1822 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1825 = dot(_1822, _1822);
    float3 _1830 = _1822 * rsqrt(fast::max(_1825, 9.9999999392252902907785028219223e-09));
    float _1834 = _1825 * float(frame.punctualLights[1].positionFalloff.w);
    float _1839 = fast::clamp(fma(-_1834, _1834, 1.0), 0.0, 1.0);
    float _1858 = fast::clamp(fma(dot(-_1830, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1867 = float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1839 * _1839) / fast::max(_1825, 9.9999997473787516355514526367188e-05)) * _1858) * _1858);
    float3 _1990 = fast::normalize(_960 + _1830);
    float _1923 = fast::clamp(dot(_954, _1830), 0.0, 1.0);
    float _1927 = fast::clamp(dot(_954, _1990), 0.0, 1.0);
    float3 _2028 = cross(_954, _1990);
    float _2031 = _1927 * params.facet_alpha;
    float _2040 = params.facet_alpha / fma(_2031, _2031, dot(_2028, _2028));
    float _2086 = 1.0 - fast::clamp(dot(_1830, _1990), 0.0, 1.0);
    float _2089 = _2086 * _2086;
    float _2130 = 8192.0 * fma(-_1923, _1234, _1923 + _1234);
    float _2134 = 1.0 / (_1392 * _2130);
    float3 _2169 = (fma(facet_environment.sample(facet_environmentSmplr, _1238, level(_1376 * 4.0)).xyz, _1383 * _1346, _1369) + fast::min(fma(fma((float3(params.facet_f0) + (_1715 * ((_1707 * _1707) * _1704))) * (((_1658 * _1658) * 0.3183098733425140380859375) * (0.5 / fma(_1541, _1681, _1234 * sqrt(fma(_1541 * _1541, _1677, _1671))))), _1292, _1582), (_1485 * _1541) * _1348, (_1383 * ((((fma(_1752, _1748, 2.0) * pow(fast::max(fma(-_1545, _1545, 1.0), 0.0), 0.5 * (_1752 * _1748))) * 0.15915493667125701904296875) * (_1541 * (_1752 * _1759))) * _1353)) * _1485), float3(65504.0))) + fast::min(fma(fma((float3(params.facet_f0) + (_1715 * ((_2089 * _2089) * _2086))) * (((_2040 * _2040) * 0.3183098733425140380859375) * (0.5 / fma(_1923, _1681, _1234 * sqrt(fma(_1923 * _1923, _1677, _1671))))), _1292, _1582), (_1867 * _1923) * _1348, (_1383 * ((((fma(_2134, _2130, 2.0) * pow(fast::max(fma(-_1927, _1927, 1.0), 0.0), 0.5 * (_2134 * _2130))) * 0.15915493667125701904296875) * (_1923 * (_2134 * _1759))) * _1353)) * _1867), float3(65504.0));
    out.fragColor = float4(_2169, 1.0);
    return out;
}

