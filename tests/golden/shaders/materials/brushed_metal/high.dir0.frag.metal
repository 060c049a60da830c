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
    half3 _641 = normalize(half3(in.v_normal));
    float3 _645 = fast::normalize(in.v_toEye);
    half3 _743 = half4(in.v_tangent).xyz;
    half3 _750 = _743 - (_641 * dot(_641, _743));
    half _752 = _641.z;
    half3 _1250;
    if (float(abs(_752)) < 0.5)
    {
        _1250 = half3(-_641.y, _641.x, half(0.0));
    }
    else
    {
        _1250 = half3(half(0.0), -_752, _641.y);
    }
    half3 _779 = normalize(half3(select(float3(_1250), float3(_750), bool3(float(dot(_750, _750)) > 0.001000000047497451305389404296875))));
    half _1012 = max(dot(_641, half3(_645)), half(9.9999997473787516355514526367188e-05));
    half _1120 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half3 _1252;
    if (float(_1120) >= 0.0)
    {
        _1252 = _779;
    }
    else
    {
        _1252 = cross(_641, _779);
    }
    half _1072 = dot(_1252, half3(_645));
    half _1079 = min(abs(_1120) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _1084 = fma(half(-float(_1079)), half(1.0) - _1012, half(1.0));
    half _1087 = _1079 * _1072;
    float4 _1127 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1012, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1156 = facet_environment.sample(facet_environmentSmplr, float3(((((_641 * _1084) + (_1252 * _1087)) * (half(512.0) * fma(_1084, _1012, _1087 * _1072))) - (half3(_645) * (half(256.0) * fma(_1084, _1084, _1087 * _1087))))), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _1036 = half4(_1156).xyz * (mix(half4(_1127).xxx, half4(_1127).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1127).y) - half(1.0)))));
    out.fragColor = float4(half4(_1036, half(1.0)));
    return out;
}

