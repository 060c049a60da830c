#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    float3 _488 = fast::normalize(in.v_normal);
    float3 _492 = fast::normalize(in.v_toEye);
    float _739 = fast::max(dot(_488, _492), 9.9999997473787516355514526367188e-05);
    float3 _743 = reflect(-_492, _488);
    float4 _778 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_739, params.facet_perceptualRoughness), level(0.0));
    float _852 = 1.0 - _739;
    float _855 = _852 * _852;
    out.fragColor = float4(mix(facet_environment.sample(facet_environmentSmplr, _743, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_778.xxx, _778.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _778.y) - 1.0)))), facet_environment.sample(facet_environmentSmplr, _743, level(fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0) * 4.0)).xyz, float3(fma(0.959999978542327880859375, (_855 * _855) * _852, 0.039999999105930328369140625) * fast::clamp(params.coat, 0.0, 1.0))), 1.0);
    return out;
}

