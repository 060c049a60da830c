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
    float3 _492 = fast::normalize(in.v_normal);
    float3 _496 = fast::normalize(in.v_toEye);
    float _743 = fast::max(dot(_492, _496), 9.9999997473787516355514526367188e-05);
    float3 _747 = reflect(-_496, _492);
    float4 _782 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_743, params.facet_perceptualRoughness), level(0.0));
    float _859 = 1.0 - _743;
    float _862 = _859 * _859;
    float _879 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    out.fragColor = float4(mix(facet_environment.sample(facet_environmentSmplr, _747, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_782.xxx, _782.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _782.y) - 1.0)))), facet_environment.sample(facet_environmentSmplr, _747, level(_879 * (4.0 * (2.0 - _879)))).xyz, float3(fma(0.959999978542327880859375, (_862 * _862) * _859, 0.039999999105930328369140625) * fast::clamp(params.coat, 0.0, 1.0))), 1.0);
    return out;
}

