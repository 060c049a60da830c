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
    float3 _622 = fast::normalize(in.v_normal);
    float3 _626 = fast::normalize(in.v_toEye);
    float3 _733 = in.v_tangent.xyz - (_622 * dot(_622, in.v_tangent.xyz));
    float _735 = _622.z;
    float3 _1208;
    if (abs(_735) < 0.5)
    {
        _1208 = float3(-_622.y, _622.x, 0.0);
    }
    else
    {
        _1208 = float3(0.0, -_735, _622.y);
    }
    float3 _762 = fast::normalize(select(_1208, _733, bool3(dot(_733, _733) > 0.001000000047497451305389404296875)));
    float _978 = fast::max(dot(_622, _626), 9.9999997473787516355514526367188e-05);
    float3 _1210;
    if (params.facet_anisotropy >= 0.0)
    {
        _1210 = _762;
    }
    else
    {
        _1210 = cross(_622, _762);
    }
    float _1038 = dot(_1210, _626);
    float _1045 = fma(-params.facet_anisotropicBend, 1.0 - _978, 1.0);
    float _1048 = params.facet_anisotropicBend * _1038;
    float4 _1087 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_978, params.facet_perceptualRoughness), level(0.0));
    out.fragColor = float4(facet_environment.sample(facet_environmentSmplr, ((((_622 * _1045) + (_1210 * _1048)) * (512.0 * fma(_1045, _978, _1048 * _1038))) - (_626 * (256.0 * fma(_1045, _1045, _1048 * _1048)))), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1087.xxx, _1087.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1087.y) - 1.0)))), 1.0);
    return out;
}

