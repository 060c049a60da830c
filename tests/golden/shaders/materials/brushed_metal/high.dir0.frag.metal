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
    half3 _637 = normalize(half3(in.v_normal));
    float3 _641 = fast::normalize(in.v_toEye);
    half3 _741 = half4(in.v_tangent).xyz;
    half3 _748 = _741 - (_637 * dot(_637, _741));
    half _750 = _637.z;
    half3 _1245;
    if (float(abs(_750)) < 0.5)
    {
        _1245 = half3(-_637.y, _637.x, half(0.0));
    }
    else
    {
        _1245 = half3(half(0.0), -_750, _637.y);
    }
    half3 _777 = normalize(half3(select(float3(_1245), float3(_748), bool3(float(dot(_748, _748)) > 0.001000000047497451305389404296875))));
    half _1010 = max(dot(_637, half3(_641)), half(9.9999997473787516355514526367188e-05));
    half _1118 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half3 _1247;
    if (float(_1118) >= 0.0)
    {
        _1247 = _777;
    }
    else
    {
        _1247 = cross(_637, _777);
    }
    half _1070 = dot(_1247, half3(_641));
    half _1077 = min(abs(_1118) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _1082 = fma(half(-float(_1077)), half(1.0) - _1010, half(1.0));
    half _1085 = _1077 * _1070;
    float4 _1125 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1010, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1151 = facet_environment.sample(facet_environmentSmplr, float3(((((_637 * _1082) + (_1247 * _1085)) * (half(512.0) * fma(_1082, _1010, _1085 * _1070))) - (half3(_641) * (half(256.0) * fma(_1082, _1082, _1085 * _1085))))), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _1034 = half4(_1151).xyz * (mix(half4(_1125).xxx, half4(_1125).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1125).y) - half(1.0)))));
    out.fragColor = float4(half4(_1034, half(1.0)));
    return out;
}

