#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    packed_float3 facet_f0;
    float facet_alpha;
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    char _m11_pad[4];
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
    float facet_sheenRoughness;
    float facet_sheenAlpha;
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
    half3 _342 = normalize(half3(in.v_normal));
    half3 _429 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    half _491 = max(dot(_342, _429), half(9.9999997473787516355514526367188e-05));
    half3 _495 = reflect(-_429, _342);
    float4 _528 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_491, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _506 = facet_environment.sample(facet_environmentSmplr, float3(_495), level(params.facet_environmentLod));
    half4 _711 = half4(facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_491, half(params.facet_sheenRoughness))), level(0.0)));
    half _581 = _711.z;
    float4 _597 = facet_environment.sample(facet_environmentSmplr, float3(_495), level(params.facet_sheenLod));
    out.fragColor = float4(half4(fma(half4(_597).xyz, half3(float3(params.facet_sheenColor)) * _581, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_506).xyz * mix(half4(_528).xxx, half4(_528).yyy, half3(float3(params.facet_f0)))) * fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _581, half(1.0))), half(1.0)));
    return out;
}

