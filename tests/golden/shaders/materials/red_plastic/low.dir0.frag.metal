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

fragment main0_out main0(main0_in in [[stage_in]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _233 = normalize(half3(in.v_normal));
    half3 _312 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    float4 _407 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_233, _312), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _385 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-_312, _233)), level(params.facet_environmentLod));
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_385).xyz * mix(half4(_407).xxx, half4(_407).yyy, half3(float3(params.facet_f0)))), half(1.0)));
    return out;
}

