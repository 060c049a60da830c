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
};

fragment main0_out main0(main0_in in [[stage_in]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]])
{
    main0_out out = {};
    half3 _243 = normalize(half3(in.v_normal));
    float3 _247 = fast::normalize(in.v_toEye);
    float4 _331 = facet_irradiance.sample(facet_irradianceSmplr, float3(_243), level(0.0));
    float4 _414 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_243, half3(_247)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _393 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_247), _243)), level(params.facet_environmentLod));
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), half4(_331).xyz, half4(_393).xyz * mix(half4(_414).xxx, half4(_414).yyy, half3(float3(params.facet_f0)))), half(1.0)));
    return out;
}

