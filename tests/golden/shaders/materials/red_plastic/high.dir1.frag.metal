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
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]])
{
    main0_out out = {};
    half3 _508 = normalize(half3(in.v_normal));
    float3 _512 = fast::normalize(in.v_toEye);
    float4 _618 = facet_irradiance.sample(facet_irradianceSmplr, float3(_508), level(0.0));
    half _665 = max(dot(_508, half3(_512)), half(9.9999997473787516355514526367188e-05));
    float4 _701 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_665, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _680 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_512), _508)), level(params.facet_environmentLod));
    half _766 = clamp(dot(_508, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    float3 _822 = fast::normalize(_512 + frame.lightDirection.xyz);
    half4 _887 = half4(cross(_508, half3(_822)), half(params.facet_alpha) * clamp(dot(_508, half3(_822)), half(0.0), half(1.0))) * half(64.0);
    half _868 = (half(4096.0) * half(params.facet_alpha)) / dot(_887, _887);
    half _912 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_822)), half(0.0), half(1.0));
    half _915 = _912 * _912;
    half3 _937 = fma(half3(float3(params.facet_diffuseColor)), half4(_618).xyz, half4(_680).xyz * mix(half4(_701).xxx, half4(_701).yyy, half3(float3(params.facet_f0)))) + min(((half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)) + ((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_915 * _915) * _912))) * min(min((_868 * _868) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _766) * _665, _766 + _665, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half4(frame.lightColor).xyz * _766), half3(float3(65504.0)));
    out.fragColor = float4(half4(_937, half(1.0)));
    return out;
}

