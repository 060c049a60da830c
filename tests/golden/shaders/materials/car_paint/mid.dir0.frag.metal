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
    half3 _409 = normalize(half3(in.v_normal));
    half3 _479 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    half _601 = max(dot(_409, _479), half(9.9999997473787516355514526367188e-05));
    half3 _605 = reflect(-_479, _409);
    float4 _643 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_601, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _619 = facet_environment.sample(facet_environmentSmplr, float3(_605), level(params.facet_environmentLod));
    half _708 = half(1.0) - _601;
    half _711 = _708 * _708;
    float4 _696 = facet_environment.sample(facet_environmentSmplr, float3(_605), level(params.facet_clearCoatLod));
    half3 _702 = mix(half4(_619).xyz * (mix(half4(_643).xxx, half4(_643).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_643).y) - half(1.0))))), half4(_696).xyz, half3(fma(half(0.959999978542327880859375), (_711 * _711) * _708, half(0.039999999105930328369140625)) * half(params.facet_clearCoat)));
    out.fragColor = float4(half4(_702, half(1.0)));
    return out;
}

