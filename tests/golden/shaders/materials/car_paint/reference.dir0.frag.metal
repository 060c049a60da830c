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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    float facet_clearCoat;
    float facet_clearCoatAlpha;
    float facet_clearCoatLod;
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
    float3 _466 = fast::normalize(in.v_normal);
    float3 _470 = fast::normalize(in.v_toEye);
    float _716 = fast::max(dot(_466, _470), 9.9999997473787516355514526367188e-05);
    float3 _720 = reflect(-_470, _466);
    float4 _758 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_716, params.facet_perceptualRoughness), level(0.0));
    float _823 = 1.0 - _716;
    float _826 = _823 * _823;
    out.fragColor = float4(mix(facet_environment.sample(facet_environmentSmplr, _720, level(params.facet_environmentLod)).xyz * (mix(_758.xxx, _758.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _758.y) - 1.0)))), facet_environment.sample(facet_environmentSmplr, _720, level(params.facet_clearCoatLod)).xyz, float3(fma(0.959999978542327880859375, (_826 * _826) * _823, 0.039999999105930328369140625) * params.facet_clearCoat)), 1.0);
    return out;
}

