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
    half3 _622 = normalize(half3(in.v_normal));
    float3 _626 = fast::normalize(in.v_toEye);
    half3 _726 = half4(in.v_tangent).xyz;
    half3 _733 = _726 - (_622 * dot(_622, _726));
    half _735 = _622.z;
    half3 _1208;
    if (float(abs(_735)) < 0.5)
    {
        _1208 = half3(-_622.y, _622.x, half(0.0));
    }
    else
    {
        _1208 = half3(half(0.0), -_735, _622.y);
    }
    half3 _762 = normalize(half3(select(float3(_1208), float3(_733), bool3(float(dot(_733, _733)) > 0.001000000047497451305389404296875))));
    half _978 = max(dot(_622, half3(_626)), half(9.9999997473787516355514526367188e-05));
    half3 _1210;
    if (params.facet_anisotropy >= 0.0)
    {
        _1210 = _762;
    }
    else
    {
        _1210 = cross(_622, _762);
    }
    half _1038 = dot(_1210, half3(_626));
    half _1045 = fma(half(-params.facet_anisotropicBend), half(1.0) - _978, half(1.0));
    half _1048 = half(params.facet_anisotropicBend) * _1038;
    float4 _1087 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_978, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1116 = facet_environment.sample(facet_environmentSmplr, float3(((((_622 * _1045) + (_1210 * _1048)) * (half(512.0) * fma(_1045, _978, _1048 * _1038))) - (half3(_626) * (half(256.0) * fma(_1045, _1045, _1048 * _1048))))), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _1002 = half4(_1116).xyz * (mix(half4(_1087).xxx, half4(_1087).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1087).y) - half(1.0)))));
    out.fragColor = float4(half4(_1002, half(1.0)));
    return out;
}

