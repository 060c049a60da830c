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
    float3 _976 = fast::normalize(in.v_normal);
    float3 _982 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1128 = _976.y;
    float _1133 = _976.z;
    float _1138 = _976.x;
    float _1256 = fast::max(dot(_976, _982), 9.9999997473787516355514526367188e-05);
    float3 _1260 = reflect(-_982, _976);
    float4 _1295 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1256, params.facet_perceptualRoughness), level(0.0));
    float3 _1314 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1295.y) - 1.0));
    float _1398 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1355 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1256, _1398), level(0.0));
    float3 _1405 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1368 = _1355.z;
    float _1370 = fma(-fast::max(_1405.x, fast::max(_1405.y, _1405.z)), _1368, 1.0);
    float _1414 = _1398 * _1398;
    float _1375 = _1355.w;
    float3 _1391 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1128)) + (frame.sh[2].xyz * _1133)) + (frame.sh[3].xyz * _1138)) + (((((frame.sh[4].xyz * (_1138 * _1128)) + (frame.sh[5].xyz * (_1128 * _1133))) + (frame.sh[6].xyz * fma(3.0 * _1133, _1133, -1.0))) + (frame.sh[7].xyz * (_1138 * _1133))) + (frame.sh[8].xyz * fma(_1138, _1138, -(_1128 * _1128)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1260, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1295.xxx, _1295.yyy, float3(params.facet_f0)) * _1314)) * _1370;
    float3 _1462 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1465 = dot(_1462, _1462);
    float3 _1470 = _1462 * rsqrt(fast::max(_1465, 9.9999999392252902907785028219223e-09));
    float _1474 = _1465 * float(frame.punctualLights[0].positionFalloff.w);
    float _1479 = fast::clamp(fma(-_1474, _1474, 1.0), 0.0, 1.0);
    float _1498 = fast::clamp(fma(dot(-_1470, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1507 = float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1479 * _1479) / fast::max(_1465, 9.9999997473787516355514526367188e-05)) * _1498) * _1498);
    float3 _1630 = fast::normalize(_982 + _1470);
    float _1563 = fast::clamp(dot(_976, _1470), 0.0, 1.0);
    float _1567 = fast::clamp(dot(_976, _1630), 0.0, 1.0);
    float _1669 = 4096.0 * params.facet_alpha;
    float3 _1688 = cross(_976, _1630) * 64.0;
    float _1691 = 64.0 * params.facet_alpha;
    float _1692 = _1567 * _1691;
    float _1675 = _1669 / fma(_1692, _1692, dot(_1688, _1688));
    float _1707 = params.facet_alpha * params.facet_alpha;
    float _1713 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1717 = sqrt(fma(_1256 * _1256, _1713, _1707));
    float _1740 = 1.0 - fast::clamp(dot(_1470, _1630), 0.0, 1.0);
    float _1743 = _1740 * _1740;
    float3 _1751 = float3(1.0) - float3(params.facet_f0);
    float _1784 = 8192.0 * fma(-_1563, _1256, _1563 + _1256);
    float _1788 = 1.0 / (_1414 * _1784);
    float _1795 = 2048.0 * _1414;
    float3 _1604 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1858 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1861 = dot(_1858, _1858);
    float3 _1866 = _1858 * rsqrt(fast::max(_1861, 9.9999999392252902907785028219223e-09));
    float _1870 = _1861 * float(frame.punctualLights[1].positionFalloff.w);
    float _1875 = fast::clamp(fma(-_1870, _1870, 1.0), 0.0, 1.0);
    float _1894 = fast::clamp(fma(dot(-_1866, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1903 = float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1875 * _1875) / fast::max(_1861, 9.9999997473787516355514526367188e-05)) * _1894) * _1894);
    float3 _2026 = fast::normalize(_982 + _1866);
    float _1959 = fast::clamp(dot(_976, _1866), 0.0, 1.0);
    float _1963 = fast::clamp(dot(_976, _2026), 0.0, 1.0);
    float3 _2084 = cross(_976, _2026) * 64.0;
    float _2088 = _1963 * _1691;
    float _2071 = _1669 / fma(_2088, _2088, dot(_2084, _2084));
    float _2136 = 1.0 - fast::clamp(dot(_1866, _2026), 0.0, 1.0);
    float _2139 = _2136 * _2136;
    float _2180 = 8192.0 * fma(-_1959, _1256, _1959 + _1256);
    float _2184 = 1.0 / (_1414 * _2180);
    float3 _2219 = (fma(facet_environment.sample(facet_environmentSmplr, _1260, level(_1398 * 4.0)).xyz, _1405 * _1368, _1391) + fast::min(fma(fma((float3(params.facet_f0) + (_1751 * ((_1743 * _1743) * _1740))) * (((_1675 * _1675) * 0.3183098733425140380859375) * (0.5 / fma(_1563, _1717, _1256 * sqrt(fma(_1563 * _1563, _1713, _1707))))), _1314, _1604), (_1507 * _1563) * _1370, (_1405 * ((((fma(_1788, _1784, 2.0) * pow(fast::max(fma(-_1567, _1567, 1.0), 0.0), 0.5 * (_1788 * _1784))) * 0.15915493667125701904296875) * (_1563 * (_1788 * _1795))) * _1375)) * _1507), float3(65504.0))) + fast::min(fma(fma((float3(params.facet_f0) + (_1751 * ((_2139 * _2139) * _2136))) * (((_2071 * _2071) * 0.3183098733425140380859375) * (0.5 / fma(_1959, _1717, _1256 * sqrt(fma(_1959 * _1959, _1713, _1707))))), _1314, _1604), (_1903 * _1959) * _1370, (_1405 * ((((fma(_2184, _2180, 2.0) * pow(fast::max(fma(-_1963, _1963, 1.0), 0.0), 0.5 * (_2184 * _2180))) * 0.15915493667125701904296875) * (_1959 * (_2184 * _1795))) * _1375)) * _1903), float3(65504.0));
    out.fragColor = float4(_2219, 1.0);
    return out;
}

