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
    float3 _637 = fast::normalize(in.v_normal);
    float3 _641 = fast::normalize(in.v_toEye);
    float3 _748 = in.v_tangent.xyz - (_637 * dot(_637, in.v_tangent.xyz));
    float _750 = _637.z;
    float3 _1245;
    if (abs(_750) < 0.5)
    {
        _1245 = float3(-_637.y, _637.x, 0.0);
    }
    else
    {
        _1245 = float3(0.0, -_750, _637.y);
    }
    float3 _777 = fast::normalize(select(_1245, _748, bool3(dot(_748, _748) > 0.001000000047497451305389404296875)));
    float _1010 = fast::max(dot(_637, _641), 9.9999997473787516355514526367188e-05);
    float _1118 = fast::clamp(params.anisotropy, -1.0, 1.0);
    float3 _1247;
    if (_1118 >= 0.0)
    {
        _1247 = _777;
    }
    else
    {
        _1247 = cross(_637, _777);
    }
    float _1070 = dot(_1247, _641);
    float _1077 = fast::min(abs(_1118) * fast::clamp(5.0 * params.facet_perceptualRoughness, 0.0, 1.0), 0.9921875);
    float _1082 = fma(-_1077, 1.0 - _1010, 1.0);
    float _1085 = _1077 * _1070;
    float4 _1125 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1010, params.facet_perceptualRoughness), level(0.0));
    out.fragColor = float4(facet_environment.sample(facet_environmentSmplr, ((((_637 * _1082) + (_1247 * _1085)) * (512.0 * fma(_1082, _1010, _1085 * _1070))) - (_641 * (256.0 * fma(_1082, _1082, _1085 * _1085)))), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1125.xxx, _1125.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1125.y) - 1.0)))), 1.0);
    return out;
}

