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
    half3 _519 = normalize(half3(in.v_normal));
    half3 _604 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    half3 _726 = reflect(-_604, _519);
    float4 _756 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_519, _604), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    half3 _765 = mix(half4(_756).xxx, half4(_756).yyy, half3(float3(params.facet_f0)));
    float4 _775 = facet_environment.sample(facet_environmentSmplr, float3(_726), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _558 = half4(frame.lightDirection).xyz;
    half _912 = clamp(dot(_726, _558), half(0.0), half(1.0));
    half _915 = _912 * _912;
    half4 _1056 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_915 * _915, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _927 = _1056.x;
    out.fragColor = float4(half4(fma(half4(_775).xyz, _765, min((_765 * ((_927 * _927) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_519, _558), half(0.0), half(1.0))), half3(float3(65504.0)))), half(1.0)));
    return out;
}

