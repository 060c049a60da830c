#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _264 = normalize(half3(in.v_normal));
    float3 _268 = fast::normalize(in.v_toEye);
    half3 _441 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _538 = half4(facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_264, half3(_268)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0)));
    half _400 = _538.z;
    float4 _457 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_268), _264)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    out.fragColor = float4(half4(fma(half4(_457).xyz, _441 * _400, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_441.x, max(_441.y, _441.z)))), _400, half(1.0))), half(1.0)));
    return out;
}

