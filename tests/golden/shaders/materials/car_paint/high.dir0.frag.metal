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
    half3 _492 = normalize(half3(in.v_normal));
    float3 _496 = fast::normalize(in.v_toEye);
    half _743 = max(dot(_492, half3(_496)), half(9.9999997473787516355514526367188e-05));
    half3 _747 = reflect(-half3(_496), _492);
    float4 _782 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_743, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _811 = facet_environment.sample(facet_environmentSmplr, float3(_747), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _859 = half(1.0) - _743;
    half _862 = _859 * _859;
    half _879 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _889 = facet_environment.sample(facet_environmentSmplr, float3(_747), level(_879 * (half(4.0) * (half(2.0) - _879))));
    half3 _853 = mix(half4(_811).xyz * (mix(half4(_782).xxx, half4(_782).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_782).y) - half(1.0))))), half4(_889).xyz, half3(fma(half(0.959999978542327880859375), (_862 * _862) * _859, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_853, half(1.0)));
    return out;
}

