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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]])
{
    main0_out out = {};
    half3 _626 = normalize(half3(in.v_normal));
    float3 _642 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _774 = facet_irradiance.sample(facet_irradianceSmplr, float3(_626), level(0.0));
    half _823 = max(dot(_626, half3(_642)), half(9.9999997473787516355514526367188e-05));
    float4 _856 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_823, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _875 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_642), _626)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _988 = fast::normalize(_642 + frame.lightDirection.xyz);
    half _935 = clamp(dot(_626, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1028 = half(4096.0) * half(params.facet_alpha);
    half4 _1053 = half4(cross(_626, half3(_988)), half(params.facet_alpha) * clamp(dot(_626, half3(_988)), half(0.0), half(1.0))) * half(64.0);
    half _1034 = _1028 / dot(_1053, _1053);
    half _1078 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_988)), half(0.0), half(1.0));
    half _1081 = _1078 * _1078;
    half3 _1089 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _963 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1139 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1142 = dot(_1139, _1139);
    float3 _1147 = _1139 * rsqrt(fast::max(_1142, 9.9999999392252902907785028219223e-09));
    float _1151 = _1142 * float(frame.punctualLights[0].positionFalloff.w);
    float _1156 = fast::clamp(fma(-_1151, _1151, 1.0), 0.0, 1.0);
    float _1175 = fast::clamp(fma(dot(-_1147, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1291 = fast::normalize(_642 + _1147);
    half _1238 = clamp(dot(_626, half3(_1147)), half(0.0), half(1.0));
    half4 _1356 = half4(cross(_626, half3(_1291)), half(params.facet_alpha) * clamp(dot(_626, half3(_1291)), half(0.0), half(1.0))) * half(64.0);
    half _1337 = _1028 / dot(_1356, _1356);
    half _1381 = half(1.0) - clamp(dot(half3(_1147), half3(_1291)), half(0.0), half(1.0));
    half _1384 = _1381 * _1381;
    half3 _1406 = (fma(half3(float3(params.facet_diffuseColor)), half4(_774).xyz, half4(_875).xyz * mix(half4(_856).xxx, half4(_856).yyy, half3(float3(params.facet_f0)))) + min((_963 + ((half3(float3(params.facet_f0)) + (_1089 * ((_1081 * _1081) * _1078))) * min(min((_1034 * _1034) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _935) * _823, _935 + _823, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half4(frame.lightColor).xyz * _935), half3(float3(65504.0)))) + min((_963 + ((half3(float3(params.facet_f0)) + (_1089 * ((_1384 * _1384) * _1381))) * min(min((_1337 * _1337) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1238) * _823, _1238 + _823, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1156) * half(_1156)) / fast::max(_1142, 9.9999997473787516355514526367188e-05)) * half(_1175)) * half(_1175)), float3(65504.0))) * _1238), half3(float3(65504.0)));
    float3 _1442 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1445 = dot(_1442, _1442);
    float3 _1450 = _1442 * rsqrt(fast::max(_1445, 9.9999999392252902907785028219223e-09));
    float _1454 = _1445 * float(frame.punctualLights[1].positionFalloff.w);
    float _1459 = fast::clamp(fma(-_1454, _1454, 1.0), 0.0, 1.0);
    float _1478 = fast::clamp(fma(dot(-_1450, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1594 = fast::normalize(_642 + _1450);
    half _1541 = clamp(dot(_626, half3(_1450)), half(0.0), half(1.0));
    half4 _1659 = half4(cross(_626, half3(_1594)), half(params.facet_alpha) * clamp(dot(_626, half3(_1594)), half(0.0), half(1.0))) * half(64.0);
    half _1640 = _1028 / dot(_1659, _1659);
    half _1684 = half(1.0) - clamp(dot(half3(_1450), half3(_1594)), half(0.0), half(1.0));
    half _1687 = _1684 * _1684;
    half3 _1709 = _1406 + min((_963 + ((half3(float3(params.facet_f0)) + (_1089 * ((_1687 * _1687) * _1684))) * min(min((_1640 * _1640) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1541) * _823, _1541 + _823, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1459) * half(_1459)) / fast::max(_1445, 9.9999997473787516355514526367188e-05)) * half(_1478)) * half(_1478)), float3(65504.0))) * _1541), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1709, half(1.0)));
    return out;
}

