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
    half3 _771 = normalize(half3(in.v_normal));
    float3 _777 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1063 = max(dot(_771, half3(_777)), half(9.9999997473787516355514526367188e-05));
    float4 _1105 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1063, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1124 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1105).y) - half(1.0)));
    float4 _1081 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_777), _771)), level(params.facet_environmentLod));
    half _1180 = clamp(dot(_771, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    float3 _1239 = fast::normalize(_777 + frame.lightDirection.xyz);
    half _1279 = half(4096.0) * half(params.facet_alpha);
    half4 _1304 = half4(cross(_771, half3(_1239)), half(params.facet_alpha) * clamp(dot(_771, half3(_1239)), half(0.0), half(1.0))) * half(64.0);
    half _1285 = _1279 / dot(_1304, _1304);
    half _1315 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1321 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1325 = sqrt(fma(_1063 * _1063, _1321, _1315));
    half _1349 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1239)), half(0.0), half(1.0));
    half _1352 = _1349 * _1349;
    half3 _1360 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1418 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1421 = dot(_1418, _1418);
    float3 _1426 = _1418 * rsqrt(fast::max(_1421, 9.9999999392252902907785028219223e-09));
    float _1430 = _1421 * float(frame.punctualLights[0].positionFalloff.w);
    float _1435 = fast::clamp(fma(-_1430, _1430, 1.0), 0.0, 1.0);
    float _1454 = fast::clamp(fma(dot(-_1426, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1514 = clamp(dot(_771, half3(_1426)), half(0.0), half(1.0));
    float3 _1573 = fast::normalize(_777 + _1426);
    half4 _1638 = half4(cross(_771, half3(_1573)), half(params.facet_alpha) * clamp(dot(_771, half3(_1573)), half(0.0), half(1.0))) * half(64.0);
    half _1619 = _1279 / dot(_1638, _1638);
    half _1683 = half(1.0) - clamp(dot(half3(_1426), half3(_1573)), half(0.0), half(1.0));
    half _1686 = _1683 * _1683;
    float3 _1752 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1755 = dot(_1752, _1752);
    float3 _1760 = _1752 * rsqrt(fast::max(_1755, 9.9999999392252902907785028219223e-09));
    float _1764 = _1755 * float(frame.punctualLights[1].positionFalloff.w);
    float _1769 = fast::clamp(fma(-_1764, _1764, 1.0), 0.0, 1.0);
    float _1788 = fast::clamp(fma(dot(-_1760, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1848 = clamp(dot(_771, half3(_1760)), half(0.0), half(1.0));
    float3 _1907 = fast::normalize(_777 + _1760);
    half4 _1972 = half4(cross(_771, half3(_1907)), half(params.facet_alpha) * clamp(dot(_771, half3(_1907)), half(0.0), half(1.0))) * half(64.0);
    half _1953 = _1279 / dot(_1972, _1972);
    half _2017 = half(1.0) - clamp(dot(half3(_1760), half3(_1907)), half(0.0), half(1.0));
    half _2020 = _2017 * _2017;
    half3 _2050 = (fma(half4(_1081).xyz, mix(half4(_1105).xxx, half4(_1105).yyy, half3(float3(params.facet_f0))) * _1124, min((((half3(float3(params.facet_f0)) + (_1360 * ((_1352 * _1352) * _1349))) * min(min((_1285 * _1285) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1180, _1325, _1063 * sqrt(fma(_1180 * _1180, _1321, _1315))), half(65504.0)), half(65504.0))) * _1124) * (half4(frame.lightColor).xyz * _1180), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1360 * ((_1686 * _1686) * _1683))) * min(min((_1619 * _1619) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1514, _1325, _1063 * sqrt(fma(_1514 * _1514, _1321, _1315))), half(65504.0)), half(65504.0))) * _1124) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1435) * half(_1435)) / fast::max(_1421, 9.9999997473787516355514526367188e-05)) * half(_1454)) * half(_1454)), float3(65504.0))) * _1514), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1360 * ((_2020 * _2020) * _2017))) * min(min((_1953 * _1953) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1848, _1325, _1063 * sqrt(fma(_1848 * _1848, _1321, _1315))), half(65504.0)), half(65504.0))) * _1124) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1769) * half(_1769)) / fast::max(_1755, 9.9999997473787516355514526367188e-05)) * half(_1788)) * half(_1788)), float3(65504.0))) * _1848), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2050, half(1.0)));
    return out;
}

