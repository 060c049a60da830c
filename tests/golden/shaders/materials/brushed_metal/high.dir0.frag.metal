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
    half3 _606 = normalize(half3(in.v_normal));
    float3 _610 = fast::normalize(in.v_toEye);
    half3 _710 = half4(in.v_tangent).xyz;
    half3 _717 = _710 - (_606 * dot(_606, _710));
    half _719 = _606.z;
    half3 _1182;
    if (float(abs(_719)) < 0.5)
    {
        _1182 = half3(-_606.y, _606.x, half(0.0));
    }
    else
    {
        _1182 = half3(half(0.0), -_719, _606.y);
    }
    half3 _746 = normalize(half3(select(float3(_1182), float3(_717), bool3(float(dot(_717, _717)) > 0.001000000047497451305389404296875))));
    half _960 = max(dot(_606, half3(_610)), half(9.9999997473787516355514526367188e-05));
    half3 _1184;
    if (params.facet_anisotropy >= 0.0)
    {
        _1184 = _746;
    }
    else
    {
        _1184 = cross(_606, _746);
    }
    half _1023 = dot(_1184, half3(_610));
    half _1030 = fma(half(-params.facet_anisotropicBend), half(1.0) - _960, half(1.0));
    half _1033 = half(params.facet_anisotropicBend) * _1023;
    float4 _1072 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_960, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _980 = facet_environment.sample(facet_environmentSmplr, float3(((((_606 * _1030) + (_1184 * _1033)) * (half(512.0) * fma(_1030, _960, _1033 * _1023))) - (half3(_610) * (half(256.0) * fma(_1030, _1030, _1033 * _1033))))), level(params.facet_environmentLod));
    half3 _987 = half4(_980).xyz * (mix(half4(_1072).xxx, half4(_1072).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1072).y) - half(1.0)))));
    out.fragColor = float4(half4(_987, half(1.0)));
    return out;
}

