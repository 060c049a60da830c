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
    float3 _482 = fast::normalize(in.v_normal);
    float3 _486 = fast::normalize(in.v_toEye);
    float _734 = fast::max(dot(_482, _486), 9.9999997473787516355514526367188e-05);
    float3 _738 = reflect(-_486, _482);
    float4 _773 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_734, params.facet_perceptualRoughness), level(0.0));
    float _849 = 1.0 - _734;
    float _852 = _849 * _849;
    out.fragColor = float4(mix(facet_environment.sample(facet_environmentSmplr, _738, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_773.xxx, _773.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _773.y) - 1.0)))), facet_environment.sample(facet_environmentSmplr, _738, level(params.facet_clearCoatLod)).xyz, float3(fma(0.959999978542327880859375, (_852 * _852) * _849, 0.039999999105930328369140625) * params.facet_clearCoat)), 1.0);
    return out;
}

