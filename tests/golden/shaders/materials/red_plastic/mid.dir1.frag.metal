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
    half3 _445 = normalize(half3(in.v_normal));
    half3 _543 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    float4 _637 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_445, _543), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _616 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-_543, _445)), level(params.facet_environmentLod));
    half3 _498 = half4(frame.lightDirection).xyz;
    half3 _706 = _543 + _498;
    half3 _716 = _706 * (half(64.0) * rsqrt(dot(_706, _706)));
    half _725 = clamp(dot(_498, _716) * half(0.015625), half(0.0), half(1.0));
    half _843 = max(_725 * _725, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _872 = half4(cross(_445, _716), half(params.facet_alpha) * clamp(dot(_445, _716), half(0.0), half(64.0)));
    half _853 = half(params.facet_ggxAlphaScaled) / (dot(_872, _872) * _843);
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_616).xyz * mix(half4(_637).xxx, half4(_637).yyy, half3(float3(params.facet_f0)))) + min((half3(float3(params.facet_f0)) * half4(frame.lightColor).xyz) * (min((_853 * _853) * _843, half(65504.0)) * clamp(dot(_445, _498), half(0.0), half(1.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

