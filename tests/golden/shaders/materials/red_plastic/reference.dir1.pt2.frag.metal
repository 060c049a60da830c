#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
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
    float3 _758 = fast::normalize(in.v_normal);
    float3 _764 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _919 = _758.y;
    float _924 = _758.z;
    float _929 = _758.x;
    float _1047 = fast::max(dot(_758, _764), 9.9999997473787516355514526367188e-05);
    float4 _1086 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1047, params.facet_perceptualRoughness), level(0.0));
    float3 _1105 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1086.y) - 1.0));
    float3 _1232 = fast::normalize(_764 + frame.lightDirection.xyz);
    float _1177 = fast::clamp(dot(_758, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1270 = cross(_758, _1232);
    float _1273 = fast::clamp(dot(_758, _1232), 0.0, 1.0) * params.facet_alpha;
    float _1282 = params.facet_alpha / fma(_1273, _1273, dot(_1270, _1270));
    float _1295 = params.facet_alpha * params.facet_alpha;
    float _1301 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1305 = sqrt(fma(_1047 * _1047, _1301, _1295));
    float _1328 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1232), 0.0, 1.0);
    float _1331 = _1328 * _1328;
    float3 _1339 = float3(1.0) - float3(params.facet_f0);
    float3 _1208 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1353 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _919)) + (frame.sh[2].xyz * _924)) + (frame.sh[3].xyz * _929)) + (((((frame.sh[4].xyz * (_929 * _919)) + (frame.sh[5].xyz * (_919 * _924))) + (frame.sh[6].xyz * fma(3.0 * _924, _924, -1.0))) + (frame.sh[7].xyz * (_929 * _924))) + (frame.sh[8].xyz * fma(_929, _929, -(_919 * _919)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_764, _758), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1086.xxx, _1086.yyy, float3(params.facet_f0)) * _1105)) + fast::min(fma((float3(params.facet_f0) + (_1339 * ((_1331 * _1331) * _1328))) * (((_1282 * _1282) * 0.3183098733425140380859375) * (0.5 / fma(_1177, _1305, _1047 * sqrt(fma(_1177 * _1177, _1301, _1295))))), _1105, _1208) * (frame.lightColor.xyz * _1177), float3(65504.0));
    float3 _1388 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1391 = dot(_1388, _1388);
    float3 _1396 = _1388 * rsqrt(fast::max(_1391, 9.9999999392252902907785028219223e-09));
    float _1400 = _1391 * float(frame.punctualLights[0].positionFalloff.w);
    float _1405 = fast::clamp(fma(-_1400, _1400, 1.0), 0.0, 1.0);
    float _1424 = fast::clamp(fma(dot(-_1396, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1539 = fast::normalize(_764 + _1396);
    float _1484 = fast::clamp(dot(_758, _1396), 0.0, 1.0);
    float3 _1577 = cross(_758, _1539);
    float _1580 = fast::clamp(dot(_758, _1539), 0.0, 1.0) * params.facet_alpha;
    float _1589 = params.facet_alpha / fma(_1580, _1580, dot(_1577, _1577));
    float _1635 = 1.0 - fast::clamp(dot(_1396, _1539), 0.0, 1.0);
    float _1638 = _1635 * _1635;
    float3 _1695 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1698 = dot(_1695, _1695);
    float3 _1703 = _1695 * rsqrt(fast::max(_1698, 9.9999999392252902907785028219223e-09));
    float _1707 = _1698 * float(frame.punctualLights[1].positionFalloff.w);
    float _1712 = fast::clamp(fma(-_1707, _1707, 1.0), 0.0, 1.0);
    float _1731 = fast::clamp(fma(dot(-_1703, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1846 = fast::normalize(_764 + _1703);
    float _1791 = fast::clamp(dot(_758, _1703), 0.0, 1.0);
    float3 _1884 = cross(_758, _1846);
    float _1887 = fast::clamp(dot(_758, _1846), 0.0, 1.0) * params.facet_alpha;
    float _1896 = params.facet_alpha / fma(_1887, _1887, dot(_1884, _1884));
    float _1942 = 1.0 - fast::clamp(dot(_1703, _1846), 0.0, 1.0);
    float _1945 = _1942 * _1942;
    float3 _1967 = (_1353 + fast::min(fma((float3(params.facet_f0) + (_1339 * ((_1638 * _1638) * _1635))) * (((_1589 * _1589) * 0.3183098733425140380859375) * (0.5 / fma(_1484, _1305, _1047 * sqrt(fma(_1484 * _1484, _1301, _1295))))), _1105, _1208) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1405 * _1405) / fast::max(_1391, 9.9999997473787516355514526367188e-05)) * _1424) * _1424)) * _1484), float3(65504.0))) + fast::min(fma((float3(params.facet_f0) + (_1339 * ((_1945 * _1945) * _1942))) * (((_1896 * _1896) * 0.3183098733425140380859375) * (0.5 / fma(_1791, _1305, _1047 * sqrt(fma(_1791 * _1791, _1301, _1295))))), _1105, _1208) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1712 * _1712) / fast::max(_1698, 9.9999997473787516355514526367188e-05)) * _1731) * _1731)) * _1791), float3(65504.0));
    out.fragColor = float4(_1967, 1.0);
    return out;
}

