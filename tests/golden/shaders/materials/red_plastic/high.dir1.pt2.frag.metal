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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]])
{
    main0_out out = {};
    half3 _612 = normalize(half3(in.v_normal));
    float3 _628 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _760 = facet_irradiance.sample(facet_irradianceSmplr, float3(_612), level(0.0));
    half _807 = max(dot(_612, half3(_628)), half(9.9999997473787516355514526367188e-05));
    float4 _843 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_807, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _822 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_628), _612)), level(params.facet_environmentLod));
    half _908 = clamp(dot(_612, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    float3 _964 = fast::normalize(_628 + frame.lightDirection.xyz);
    half _1004 = half(4096.0) * half(params.facet_alpha);
    half4 _1029 = half4(cross(_612, half3(_964)), half(params.facet_alpha) * clamp(dot(_612, half3(_964)), half(0.0), half(1.0))) * half(64.0);
    half _1010 = _1004 / dot(_1029, _1029);
    half _1054 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_964)), half(0.0), half(1.0));
    half _1057 = _1054 * _1054;
    half3 _1065 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _939 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1115 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1118 = dot(_1115, _1115);
    float3 _1123 = _1115 * rsqrt(fast::max(_1118, 9.9999999392252902907785028219223e-09));
    float _1127 = _1118 * float(frame.punctualLights[0].positionFalloff.w);
    float _1132 = fast::clamp(fma(-_1127, _1127, 1.0), 0.0, 1.0);
    float _1151 = fast::clamp(fma(dot(-_1123, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1211 = clamp(dot(_612, half3(_1123)), half(0.0), half(1.0));
    float3 _1267 = fast::normalize(_628 + _1123);
    half4 _1332 = half4(cross(_612, half3(_1267)), half(params.facet_alpha) * clamp(dot(_612, half3(_1267)), half(0.0), half(1.0))) * half(64.0);
    half _1313 = _1004 / dot(_1332, _1332);
    half _1357 = half(1.0) - clamp(dot(half3(_1123), half3(_1267)), half(0.0), half(1.0));
    half _1360 = _1357 * _1357;
    half3 _1382 = (fma(half3(float3(params.facet_diffuseColor)), half4(_760).xyz, half4(_822).xyz * mix(half4(_843).xxx, half4(_843).yyy, half3(float3(params.facet_f0)))) + min((_939 + ((half3(float3(params.facet_f0)) + (_1065 * ((_1057 * _1057) * _1054))) * min(min((_1010 * _1010) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _908) * _807, _908 + _807, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half4(frame.lightColor).xyz * _908), half3(float3(65504.0)))) + min((_939 + ((half3(float3(params.facet_f0)) + (_1065 * ((_1360 * _1360) * _1357))) * min(min((_1313 * _1313) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1211) * _807, _1211 + _807, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1132) * half(_1132)) / fast::max(_1118, 9.9999997473787516355514526367188e-05)) * half(_1151)) * half(_1151)), float3(65504.0))) * _1211), half3(float3(65504.0)));
    float3 _1418 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1421 = dot(_1418, _1418);
    float3 _1426 = _1418 * rsqrt(fast::max(_1421, 9.9999999392252902907785028219223e-09));
    float _1430 = _1421 * float(frame.punctualLights[1].positionFalloff.w);
    float _1435 = fast::clamp(fma(-_1430, _1430, 1.0), 0.0, 1.0);
    float _1454 = fast::clamp(fma(dot(-_1426, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1514 = clamp(dot(_612, half3(_1426)), half(0.0), half(1.0));
    float3 _1570 = fast::normalize(_628 + _1426);
    half4 _1635 = half4(cross(_612, half3(_1570)), half(params.facet_alpha) * clamp(dot(_612, half3(_1570)), half(0.0), half(1.0))) * half(64.0);
    half _1616 = _1004 / dot(_1635, _1635);
    half _1660 = half(1.0) - clamp(dot(half3(_1426), half3(_1570)), half(0.0), half(1.0));
    half _1663 = _1660 * _1660;
    half3 _1685 = _1382 + min((_939 + ((half3(float3(params.facet_f0)) + (_1065 * ((_1663 * _1663) * _1660))) * min(min((_1616 * _1616) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1514) * _807, _1514 + _807, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1435) * half(_1435)) / fast::max(_1421, 9.9999997473787516355514526367188e-05)) * half(_1454)) * half(_1454)), float3(65504.0))) * _1514), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1685, half(1.0)));
    return out;
}

