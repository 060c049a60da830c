#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    float facet_alpha;
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
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
    half3 _289 = normalize(half3(in.v_normal));
    half3 _362 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    float4 _394 = facet_irradiance.sample(facet_irradianceSmplr, float3(_289), level(0.0));
    half4 _584 = half4(facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_289, _362), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0)));
    half _452 = _584.z;
    float4 _468 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-_362, _289)), level(params.facet_sheenLod));
    out.fragColor = float4(half4(fma(half4(_468).xyz, half3(float3(params.facet_sheenColor)) * _452, (half3(float3(params.facet_diffuseColor)) * half4(_394).xyz) * fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _452, half(1.0))), half(1.0)));
    return out;
}

