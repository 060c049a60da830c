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
    half3 _351 = normalize(half3(in.v_normal));
    float3 _355 = fast::normalize(in.v_toEye);
    half _490 = max(dot(_351, half3(_355)), half(9.9999997473787516355514526367188e-05));
    half3 _494 = reflect(-half3(_355), _351);
    float4 _524 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_490, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _543 = facet_environment.sample(facet_environmentSmplr, float3(_494), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _620 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    half3 _627 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _750 = half4(facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_490, _620)), level(0.0)));
    half _590 = _750.z;
    float4 _651 = facet_environment.sample(facet_environmentSmplr, float3(_494), level(_620 * (half(4.0) * (half(2.0) - _620))));
    out.fragColor = float4(half4(fma(half4(_651).xyz, _627 * _590, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_543).xyz * mix(half4(_524).xxx, half4(_524).yyy, half3(float3(params.facet_f0)))) * fma(half(-float(max(_627.x, max(_627.y, _627.z)))), _590, half(1.0))), half(1.0)));
    return out;
}

