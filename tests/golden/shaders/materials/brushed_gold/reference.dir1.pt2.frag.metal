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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    float3 _762 = fast::normalize(in.v_normal);
    float3 _768 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1054 = fast::max(dot(_762, _768), 9.9999997473787516355514526367188e-05);
    float4 _1096 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1054, params.facet_perceptualRoughness), level(0.0));
    float3 _1115 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1096.y) - 1.0));
    float _1171 = fast::clamp(dot(_762, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1229 = fast::normalize(_768 + frame.lightDirection.xyz);
    float _1267 = 4096.0 * params.facet_alpha;
    float4 _1291 = float4(cross(_762, _1229), params.facet_alpha * fast::clamp(dot(_762, _1229), 0.0, 1.0)) * 64.0;
    float _1273 = _1267 / dot(_1291, _1291);
    float _1302 = params.facet_alpha * params.facet_alpha;
    float _1308 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1312 = sqrt(fma(_1054 * _1054, _1308, _1302));
    float _1335 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1229), 0.0, 1.0);
    float _1338 = _1335 * _1335;
    float3 _1346 = float3(1.0) - float3(params.facet_f0);
    float3 _1403 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1406 = dot(_1403, _1403);
    float3 _1411 = _1403 * rsqrt(fast::max(_1406, 9.9999999392252902907785028219223e-09));
    float _1415 = _1406 * float(frame.punctualLights[0].positionFalloff.w);
    float _1420 = fast::clamp(fma(-_1415, _1415, 1.0), 0.0, 1.0);
    float _1439 = fast::clamp(fma(dot(-_1411, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1496 = fast::clamp(dot(_762, _1411), 0.0, 1.0);
    float3 _1554 = fast::normalize(_768 + _1411);
    float4 _1616 = float4(cross(_762, _1554), params.facet_alpha * fast::clamp(dot(_762, _1554), 0.0, 1.0)) * 64.0;
    float _1598 = _1267 / dot(_1616, _1616);
    float _1660 = 1.0 - fast::clamp(dot(_1411, _1554), 0.0, 1.0);
    float _1663 = _1660 * _1660;
    float3 _1728 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1731 = dot(_1728, _1728);
    float3 _1736 = _1728 * rsqrt(fast::max(_1731, 9.9999999392252902907785028219223e-09));
    float _1740 = _1731 * float(frame.punctualLights[1].positionFalloff.w);
    float _1745 = fast::clamp(fma(-_1740, _1740, 1.0), 0.0, 1.0);
    float _1764 = fast::clamp(fma(dot(-_1736, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1821 = fast::clamp(dot(_762, _1736), 0.0, 1.0);
    float3 _1879 = fast::normalize(_768 + _1736);
    float4 _1941 = float4(cross(_762, _1879), params.facet_alpha * fast::clamp(dot(_762, _1879), 0.0, 1.0)) * 64.0;
    float _1923 = _1267 / dot(_1941, _1941);
    float _1985 = 1.0 - fast::clamp(dot(_1736, _1879), 0.0, 1.0);
    float _1988 = _1985 * _1985;
    float3 _2018 = (fma(facet_environment.sample(facet_environmentSmplr, reflect(-_768, _762), level(params.facet_environmentLod)).xyz, mix(_1096.xxx, _1096.yyy, float3(params.facet_f0)) * _1115, fast::min((((float3(params.facet_f0) + (_1346 * ((_1338 * _1338) * _1335))) * (((_1273 * _1273) * 0.3183098733425140380859375) * (0.5 / fma(_1171, _1312, _1054 * sqrt(fma(_1171 * _1171, _1308, _1302)))))) * _1115) * (frame.lightColor.xyz * _1171), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1346 * ((_1663 * _1663) * _1660))) * (((_1598 * _1598) * 0.3183098733425140380859375) * (0.5 / fma(_1496, _1312, _1054 * sqrt(fma(_1496 * _1496, _1308, _1302)))))) * _1115) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1420 * _1420) / fast::max(_1406, 9.9999997473787516355514526367188e-05)) * _1439) * _1439)) * _1496), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1346 * ((_1988 * _1988) * _1985))) * (((_1923 * _1923) * 0.3183098733425140380859375) * (0.5 / fma(_1821, _1312, _1054 * sqrt(fma(_1821 * _1821, _1308, _1302)))))) * _1115) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1745 * _1745) / fast::max(_1731, 9.9999997473787516355514526367188e-05)) * _1764) * _1764)) * _1821), float3(65504.0));
    out.fragColor = float4(_2018, 1.0);
    return out;
}

