#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float anisotropy;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
    packed_float3 facet_f0;
    float facet_alpha;
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    float facet_anisotropy;
    float facet_anisotropicBend;
    float2 facet_anisotropicAlpha;
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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _502 = normalize(half3(in.v_normal));
    half3 _587 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    half3 _707 = reflect(-_587, _502);
    float4 _740 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_502, _587), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    half3 _749 = mix(half4(_740).xxx, half4(_740).yyy, half3(float3(params.facet_f0)));
    float4 _718 = facet_environment.sample(facet_environmentSmplr, float3(_707), level(params.facet_environmentLod));
    half3 _541 = half4(frame.lightDirection).xyz;
    half _885 = clamp(dot(_707, _541), half(0.0), half(1.0));
    half _888 = _885 * _885;
    half4 _1025 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_888 * _888, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _900 = _1025.x;
    out.fragColor = float4(half4(fma(half4(_718).xyz, _749, min((_749 * ((_900 * _900) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_502, _541), half(0.0), half(1.0))), half3(float3(65504.0)))), half(1.0)));
    return out;
}

