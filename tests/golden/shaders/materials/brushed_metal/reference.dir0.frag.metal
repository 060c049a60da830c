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
    float3 _746 = in.v_tangent.xyz - (_637 * dot(_637, in.v_tangent.xyz));
    float _748 = _637.z;
    float3 _1243;
    if (abs(_748) < 0.5)
    {
        _1243 = float3(-_637.y, _637.x, 0.0);
    }
    else
    {
        _1243 = float3(0.0, -_748, _637.y);
    }
    float3 _775 = fast::normalize(select(_1243, _746, bool3(dot(_746, _746) > 0.001000000047497451305389404296875)));
    float _1008 = fast::max(dot(_637, _641), 9.9999997473787516355514526367188e-05);
    float _1116 = fast::clamp(params.anisotropy, -1.0, 1.0);
    float3 _1245;
    if (_1116 >= 0.0)
    {
        _1245 = _775;
    }
    else
    {
        _1245 = cross(_637, _775);
    }
    float _1068 = dot(_1245, _641);
    float _1075 = fast::min(abs(_1116) * fast::clamp(5.0 * params.facet_perceptualRoughness, 0.0, 1.0), 0.9921875);
    float _1080 = fma(-_1075, 1.0 - _1008, 1.0);
    float _1083 = _1075 * _1068;
    float4 _1123 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1008, params.facet_perceptualRoughness), level(0.0));
    out.fragColor = float4(facet_environment.sample(facet_environmentSmplr, ((((_637 * _1080) + (_1245 * _1083)) * (512.0 * fma(_1080, _1008, _1083 * _1068))) - (_641 * (256.0 * fma(_1080, _1080, _1083 * _1083)))), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1123.xxx, _1123.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1123.y) - 1.0)))), 1.0);
    return out;
}

