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
};

struct main0_out
{
    float4 fragColor [[color(0)]];
};

struct main0_in
{
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float4 v_tangent [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _377 = normalize(half3(in.v_normal));
    float3 _381 = fast::normalize(in.v_toEye);
    half3 _476 = half4(in.v_tangent).xyz;
    half _529 = max(dot(_377, half3(_381)), half(9.9999997473787516355514526367188e-05));
    half _637 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half3 _759;
    if (float(_637) >= 0.0)
    {
        _759 = _476;
    }
    else
    {
        _759 = cross(_377, _476);
    }
    half _589 = dot(_759, half3(_381));
    half _596 = min(abs(_637) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _601 = fma(half(-float(_596)), half(1.0) - _529, half(1.0));
    half _604 = _596 * _589;
    float4 _644 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_529, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _670 = facet_environment.sample(facet_environmentSmplr, float3(((((_377 * _601) + (_759 * _604)) * (half(512.0) * fma(_601, _529, _604 * _589))) - (half3(_381) * (half(256.0) * fma(_601, _601, _604 * _604))))), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _553 = half4(_670).xyz * (mix(half4(_644).xxx, half4(_644).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_644).y) - half(1.0)))));
    out.fragColor = float4(half4(_553, half(1.0)));
    return out;
}

