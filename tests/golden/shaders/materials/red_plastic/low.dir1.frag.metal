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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _411 = normalize(half3(in.v_normal));
    half3 _509 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    half3 _571 = reflect(-_509, _411);
    float4 _604 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_411, _509), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    half3 _613 = mix(half4(_604).xxx, half4(_604).yyy, half3(float3(params.facet_f0)));
    float4 _582 = facet_environment.sample(facet_environmentSmplr, float3(_571), level(params.facet_environmentLod));
    half3 _463 = half4(frame.lightDirection).xyz;
    half _741 = clamp(dot(_571, _463), half(0.0), half(1.0));
    half _744 = _741 * _741;
    half4 _853 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_744 * _744, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _756 = _853.x;
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_582).xyz * _613) + min((_613 * ((_756 * _756) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_411, _463), half(0.0), half(1.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

