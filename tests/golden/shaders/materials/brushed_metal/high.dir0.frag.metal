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
    half3 _739 = half4(in.v_tangent).xyz;
    half3 _746 = _739 - (_637 * dot(_637, _739));
    half _748 = _637.z;
    half3 _1243;
    if (float(abs(_748)) < 0.5)
    {
        _1243 = half3(-_637.y, _637.x, half(0.0));
    }
    else
    {
        _1243 = half3(half(0.0), -_748, _637.y);
    }
    half3 _775 = normalize(half3(select(float3(_1243), float3(_746), bool3(float(dot(_746, _746)) > 0.001000000047497451305389404296875))));
    half _1008 = max(dot(_637, half3(_641)), half(9.9999997473787516355514526367188e-05));
    half _1116 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half3 _1245;
    if (float(_1116) >= 0.0)
    {
        _1245 = _775;
    }
    else
    {
        _1245 = cross(_637, _775);
    }
    half _1068 = dot(_1245, half3(_641));
    half _1075 = min(abs(_1116) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _1080 = fma(half(-float(_1075)), half(1.0) - _1008, half(1.0));
    half _1083 = _1075 * _1068;
    float4 _1123 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1008, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1149 = facet_environment.sample(facet_environmentSmplr, float3(((((_637 * _1080) + (_1245 * _1083)) * (half(512.0) * fma(_1080, _1008, _1083 * _1068))) - (half3(_641) * (half(256.0) * fma(_1080, _1080, _1083 * _1083))))), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _1032 = half4(_1149).xyz * (mix(half4(_1123).xxx, half4(_1123).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1123).y) - half(1.0)))));
    out.fragColor = float4(half4(_1032, half(1.0)));
    return out;
}

