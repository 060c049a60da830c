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
    half3 _643 = normalize(half3(in.v_normal));
    float3 _647 = fast::normalize(in.v_toEye);
    half3 _745 = half4(in.v_tangent).xyz;
    half3 _752 = _745 - (_643 * dot(_643, _745));
    half _754 = _643.z;
    half3 _1254;
    if (float(abs(_754)) < 0.5)
    {
        _1254 = half3(-_643.y, _643.x, half(0.0));
    }
    else
    {
        _1254 = half3(half(0.0), -_754, _643.y);
    }
    half3 _781 = normalize(half3(select(float3(_1254), float3(_752), bool3(float(dot(_752, _752)) > 0.001000000047497451305389404296875))));
    half _1014 = max(dot(_643, half3(_647)), half(9.9999997473787516355514526367188e-05));
    half _1122 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half3 _1256;
    if (float(_1122) >= 0.0)
    {
        _1256 = _781;
    }
    else
    {
        _1256 = cross(_643, _781);
    }
    half _1074 = dot(_1256, half3(_647));
    half _1081 = min(abs(_1122) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _1086 = fma(half(-float(_1081)), half(1.0) - _1014, half(1.0));
    half _1089 = _1081 * _1074;
    float4 _1129 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1014, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1160 = facet_environment.sample(facet_environmentSmplr, float3(((((_643 * _1086) + (_1256 * _1089)) * (half(512.0) * fma(_1086, _1014, _1089 * _1074))) - (half3(_647) * (half(256.0) * fma(_1086, _1086, _1089 * _1089))))), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _1038 = half4(_1160).xyz * (mix(half4(_1129).xxx, half4(_1129).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1129).y) - half(1.0)))));
    out.fragColor = float4(half4(_1038, half(1.0)));
    return out;
}

