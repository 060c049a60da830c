#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float facet_perceptualRoughness;
    char _m3_pad[12];
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
    float3 _778 = fast::normalize(in.v_normal);
    float3 _784 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1072 = fast::max(dot(_778, _784), 9.9999997473787516355514526367188e-05);
    float4 _1111 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1072, params.facet_perceptualRoughness), level(0.0));
    float3 _1130 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1111.y) - 1.0));
    float3 _1252 = fast::normalize(_784 + frame.lightDirection.xyz);
    float _1197 = fast::clamp(dot(_778, frame.lightDirection.xyz), 0.0, 1.0);
    float _1291 = 4096.0 * params.facet_alpha;
    float3 _1310 = cross(_778, _1252) * 64.0;
    float _1313 = 64.0 * params.facet_alpha;
    float _1314 = fast::clamp(dot(_778, _1252), 0.0, 1.0) * _1313;
    float _1297 = _1291 / fma(_1314, _1314, dot(_1310, _1310));
    float _1329 = params.facet_alpha * params.facet_alpha;
    float _1335 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1339 = sqrt(fma(_1072 * _1072, _1335, _1329));
    float _1362 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1252), 0.0, 1.0);
    float _1365 = _1362 * _1362;
    float3 _1373 = float3(1.0) - float3(params.facet_f0);
    float3 _1430 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1433 = dot(_1430, _1430);
    float3 _1438 = _1430 * rsqrt(fast::max(_1433, 9.9999999392252902907785028219223e-09));
    float _1442 = _1433 * float(frame.punctualLights[0].positionFalloff.w);
    float _1447 = fast::clamp(fma(-_1442, _1442, 1.0), 0.0, 1.0);
    float _1466 = fast::clamp(fma(dot(-_1438, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1581 = fast::normalize(_784 + _1438);
    float _1526 = fast::clamp(dot(_778, _1438), 0.0, 1.0);
    float3 _1639 = cross(_778, _1581) * 64.0;
    float _1643 = fast::clamp(dot(_778, _1581), 0.0, 1.0) * _1313;
    float _1626 = _1291 / fma(_1643, _1643, dot(_1639, _1639));
    float _1691 = 1.0 - fast::clamp(dot(_1438, _1581), 0.0, 1.0);
    float _1694 = _1691 * _1691;
    float3 _1759 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1762 = dot(_1759, _1759);
    float3 _1767 = _1759 * rsqrt(fast::max(_1762, 9.9999999392252902907785028219223e-09));
    float _1771 = _1762 * float(frame.punctualLights[1].positionFalloff.w);
    float _1776 = fast::clamp(fma(-_1771, _1771, 1.0), 0.0, 1.0);
    float _1795 = fast::clamp(fma(dot(-_1767, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1910 = fast::normalize(_784 + _1767);
    float _1855 = fast::clamp(dot(_778, _1767), 0.0, 1.0);
    float3 _1968 = cross(_778, _1910) * 64.0;
    float _1972 = fast::clamp(dot(_778, _1910), 0.0, 1.0) * _1313;
    float _1955 = _1291 / fma(_1972, _1972, dot(_1968, _1968));
    float _2020 = 1.0 - fast::clamp(dot(_1767, _1910), 0.0, 1.0);
    float _2023 = _2020 * _2020;
    float3 _2053 = (fma(facet_environment.sample(facet_environmentSmplr, reflect(-_784, _778), level(params.facet_perceptualRoughness * 4.0)).xyz, mix(_1111.xxx, _1111.yyy, float3(params.facet_f0)) * _1130, fast::min((((float3(params.facet_f0) + (_1373 * ((_1365 * _1365) * _1362))) * (((_1297 * _1297) * 0.3183098733425140380859375) * (0.5 / fma(_1197, _1339, _1072 * sqrt(fma(_1197 * _1197, _1335, _1329)))))) * _1130) * (frame.lightColor.xyz * _1197), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1373 * ((_1694 * _1694) * _1691))) * (((_1626 * _1626) * 0.3183098733425140380859375) * (0.5 / fma(_1526, _1339, _1072 * sqrt(fma(_1526 * _1526, _1335, _1329)))))) * _1130) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1447 * _1447) / fast::max(_1433, 9.9999997473787516355514526367188e-05)) * _1466) * _1466)) * _1526), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1373 * ((_2023 * _2023) * _2020))) * (((_1955 * _1955) * 0.3183098733425140380859375) * (0.5 / fma(_1855, _1339, _1072 * sqrt(fma(_1855 * _1855, _1335, _1329)))))) * _1130) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1776 * _1776) / fast::max(_1762, 9.9999997473787516355514526367188e-05)) * _1795) * _1795)) * _1855), float3(65504.0));
    out.fragColor = float4(_2053, 1.0);
    return out;
}

