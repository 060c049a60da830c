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
    float3 _954 = fast::normalize(in.v_normal);
    float3 _960 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1243 = fast::max(dot(_954, _960), 9.9999997473787516355514526367188e-05);
    float3 _1247 = reflect(-_960, _954);
    float4 _1282 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1243, params.facet_perceptualRoughness), level(0.0));
    float3 _1301 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1282.y) - 1.0));
    float _1361 = 1.0 - _1243;
    float _1364 = _1361 * _1361;
    float _1371 = fma(0.959999978542327880859375, (_1364 * _1364) * _1361, 0.039999999105930328369140625);
    float _1376 = fast::clamp(params.coat, 0.0, 1.0);
    float _1343 = fma(-_1371, _1376, 1.0);
    float _1381 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1429 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1432 = dot(_1429, _1429);
    float3 _1437 = _1429 * rsqrt(fast::max(_1432, 9.9999999392252902907785028219223e-09));
    float _1441 = _1432 * float(frame.punctualLights[0].positionFalloff.w);
    float _1446 = fast::clamp(fma(-_1441, _1441, 1.0), 0.0, 1.0);
    float _1465 = fast::clamp(fma(dot(-_1437, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1597 = fast::normalize(_960 + _1437);
    float _1531 = fast::clamp(dot(_954, _1437), 0.0, 1.0);
    float _1535 = fast::clamp(dot(_954, _1597), 0.0, 1.0);
    float _1539 = fast::clamp(dot(_1437, _1597), 0.0, 1.0);
    float3 _1635 = cross(_954, _1597);
    float _1638 = _1535 * params.facet_alpha;
    float _1642 = dot(_1635, _1635);
    float _1647 = params.facet_alpha / fma(_1638, _1638, _1642);
    float _1660 = params.facet_alpha * params.facet_alpha;
    float _1666 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1670 = sqrt(fma(_1243 * _1243, _1666, _1660));
    float _1693 = 1.0 - _1539;
    float _1696 = _1693 * _1693;
    float _1701 = (_1696 * _1696) * _1693;
    float3 _1704 = float3(1.0) - float3(params.facet_f0);
    float3 _1557 = (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1446 * _1446) / fast::max(_1432, 9.9999997473787516355514526367188e-05)) * _1465) * _1465)) * _1531;
    float _1738 = _1381 * _1381;
    float _1744 = _1535 * _1738;
    float _1755 = fast::max(_1539 * _1539, 6.103515625e-05);
    float _1758 = 2048.0 * _1738;
    float _1763 = _1758 / (fma(_1744, _1744, _1642) * (_1755 * 25735.927734375));
    float3 _1860 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1863 = dot(_1860, _1860);
    float3 _1868 = _1860 * rsqrt(fast::max(_1863, 9.9999999392252902907785028219223e-09));
    float _1872 = _1863 * float(frame.punctualLights[1].positionFalloff.w);
    float _1877 = fast::clamp(fma(-_1872, _1872, 1.0), 0.0, 1.0);
    float _1896 = fast::clamp(fma(dot(-_1868, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2028 = fast::normalize(_960 + _1868);
    float _1962 = fast::clamp(dot(_954, _1868), 0.0, 1.0);
    float _1966 = fast::clamp(dot(_954, _2028), 0.0, 1.0);
    float _1970 = fast::clamp(dot(_1868, _2028), 0.0, 1.0);
    float3 _2066 = cross(_954, _2028);
    float _2069 = _1966 * params.facet_alpha;
    float _2073 = dot(_2066, _2066);
    float _2078 = params.facet_alpha / fma(_2069, _2069, _2073);
    float _2124 = 1.0 - _1970;
    float _2127 = _2124 * _2124;
    float _2132 = (_2127 * _2127) * _2124;
    float3 _1988 = (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1877 * _1877) / fast::max(_1863, 9.9999997473787516355514526367188e-05)) * _1896) * _1896)) * _1962;
    float _2175 = _1966 * _1738;
    float _2186 = fast::max(_1970 * _1970, 6.103515625e-05);
    float _2194 = _1758 / (fma(_2175, _2175, _2073) * (_2186 * 25735.927734375));
    float3 _2256 = (mix(facet_environment.sample(facet_environmentSmplr, _1247, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1282.xxx, _1282.yyy, float3(params.facet_f0)) * _1301), facet_environment.sample(facet_environmentSmplr, _1247, level(_1381 * (4.0 * (2.0 - _1381)))).xyz, float3(_1371 * _1376)) + fast::min(fma(((float3(params.facet_f0) + (_1704 * _1701)) * (((_1647 * _1647) * 0.3183098733425140380859375) * (0.5 / fma(_1531, _1670, _1243 * sqrt(fma(_1531 * _1531, _1666, _1660)))))) * _1301, _1557 * _1343, _1557 * ((_1763 * (_1763 * (12.56637096405029296875 * _1755))) * (fma(0.959999978542327880859375, _1701, 0.039999999105930328369140625) * _1376))), float3(65504.0))) + fast::min(fma(((float3(params.facet_f0) + (_1704 * _2132)) * (((_2078 * _2078) * 0.3183098733425140380859375) * (0.5 / fma(_1962, _1670, _1243 * sqrt(fma(_1962 * _1962, _1666, _1660)))))) * _1301, _1988 * _1343, _1988 * ((_2194 * (_2194 * (12.56637096405029296875 * _2186))) * (fma(0.959999978542327880859375, _2132, 0.039999999105930328369140625) * _1376))), float3(65504.0));
    out.fragColor = float4(_2256, 1.0);
    return out;
}

