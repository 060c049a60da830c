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
    float3 _497 = fast::normalize(in.v_normal);
    float3 _501 = fast::normalize(in.v_toEye);
    float _748 = fast::max(dot(_497, _501), 9.9999997473787516355514526367188e-05);
    float3 _752 = reflect(-_501, _497);
    float4 _787 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_748, params.facet_perceptualRoughness), level(0.0));
    float _863 = fast::clamp(params.coat, 0.0, 1.0);
    float _869 = 1.0 - _748;
    float _872 = _869 * _869;
    float _888 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    out.fragColor = float4(mix(facet_environment.sample(facet_environmentSmplr, _752, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_787.xxx, _787.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _787.y) - 1.0)))), facet_environment.sample(facet_environmentSmplr, _752, level(_888 * (4.0 * (2.0 - _888)))).xyz, float3(fma(0.039999999105930328369140625, _863, (0.959999978542327880859375 * _863) * ((_872 * _872) * _869)))), 1.0);
    return out;
}

