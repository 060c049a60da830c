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
    float3 _641 = fast::normalize(in.v_normal);
    float3 _645 = fast::normalize(in.v_toEye);
    float3 _750 = in.v_tangent.xyz - (_641 * dot(_641, in.v_tangent.xyz));
    float _752 = _641.z;
    float3 _1250;
    if (abs(_752) < 0.5)
    {
        _1250 = float3(-_641.y, _641.x, 0.0);
    }
    else
    {
        _1250 = float3(0.0, -_752, _641.y);
    }
    float3 _779 = fast::normalize(select(_1250, _750, bool3(dot(_750, _750) > 0.001000000047497451305389404296875)));
    float _1012 = fast::max(dot(_641, _645), 9.9999997473787516355514526367188e-05);
    float _1120 = fast::clamp(params.anisotropy, -1.0, 1.0);
    float3 _1252;
    if (_1120 >= 0.0)
    {
        _1252 = _779;
    }
    else
    {
        _1252 = cross(_641, _779);
    }
    float _1072 = dot(_1252, _645);
    float _1079 = fast::min(abs(_1120) * fast::clamp(5.0 * params.facet_perceptualRoughness, 0.0, 1.0), 0.9921875);
    float _1084 = fma(-_1079, 1.0 - _1012, 1.0);
    float _1087 = _1079 * _1072;
    float4 _1127 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1012, params.facet_perceptualRoughness), level(0.0));
    out.fragColor = float4(facet_environment.sample(facet_environmentSmplr, ((((_641 * _1084) + (_1252 * _1087)) * (512.0 * fma(_1084, _1012, _1087 * _1072))) - (_645 * (256.0 * fma(_1084, _1084, _1087 * _1087)))), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1127.xxx, _1127.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1127.y) - 1.0)))), 1.0);
    return out;
}

