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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _460 = normalize(half3(in.v_normal));
    half3 _558 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    float4 _652 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_460, _558), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _631 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-_558, _460)), level(params.facet_environmentLod));
    half3 _513 = half4(frame.lightDirection).xyz;
    half3 _721 = _558 + _513;
    half3 _731 = _721 * (half(64.0) * rsqrt(dot(_721, _721)));
    half _740 = clamp(dot(_513, _731) * half(0.015625), half(0.0), half(1.0));
    half _869 = max(_740 * _740, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _891 = half4(cross(_460, _731), half(params.facet_alpha) * clamp(dot(_460, _731), half(0.0), half(64.0)));
    half _902 = half(params.facet_ggxAlphaScaled) / (dot(_891, _891) * _869);
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_631).xyz * mix(half4(_652).xxx, half4(_652).yyy, half3(float3(params.facet_f0)))) + min((half3(float3(params.facet_f0)) * half4(frame.lightColor).xyz) * (min((_902 * _902) * _869, half(65504.0)) * clamp(dot(_460, _513), half(0.0), half(1.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

