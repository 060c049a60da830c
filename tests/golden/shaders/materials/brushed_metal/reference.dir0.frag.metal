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
    float3 _643 = fast::normalize(in.v_normal);
    float3 _647 = fast::normalize(in.v_toEye);
    float3 _752 = in.v_tangent.xyz - (_643 * dot(_643, in.v_tangent.xyz));
    float _754 = _643.z;
    float3 _1254;
    if (abs(_754) < 0.5)
    {
        _1254 = float3(-_643.y, _643.x, 0.0);
    }
    else
    {
        _1254 = float3(0.0, -_754, _643.y);
    }
    float3 _781 = fast::normalize(select(_1254, _752, bool3(dot(_752, _752) > 0.001000000047497451305389404296875)));
    float _1014 = fast::max(dot(_643, _647), 9.9999997473787516355514526367188e-05);
    float _1122 = fast::clamp(params.anisotropy, -1.0, 1.0);
    float3 _1256;
    if (_1122 >= 0.0)
    {
        _1256 = _781;
    }
    else
    {
        _1256 = cross(_643, _781);
    }
    float _1074 = dot(_1256, _647);
    float _1081 = fast::min(abs(_1122) * fast::clamp(5.0 * params.facet_perceptualRoughness, 0.0, 1.0), 0.9921875);
    float _1086 = fma(-_1081, 1.0 - _1014, 1.0);
    float _1089 = _1081 * _1074;
    float4 _1129 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1014, params.facet_perceptualRoughness), level(0.0));
    out.fragColor = float4(facet_environment.sample(facet_environmentSmplr, ((((_643 * _1086) + (_1256 * _1089)) * (512.0 * fma(_1086, _1014, _1089 * _1074))) - (_647 * (256.0 * fma(_1086, _1086, _1089 * _1089)))), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1129.xxx, _1129.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1129.y) - 1.0)))), 1.0);
    return out;
}

