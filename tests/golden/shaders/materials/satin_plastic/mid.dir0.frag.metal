#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _368 = normalize(half3(in.v_normal));
    float3 _372 = fast::normalize(in.v_toEye);
    half _505 = max(dot(_368, half3(_372)), half(9.9999997473787516355514526367188e-05));
    half3 _509 = reflect(-half3(_372), _368);
    float4 _544 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_505, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _570 = facet_environment.sample(facet_environmentSmplr, float3(_509), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _647 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    half3 _654 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _778 = half4(facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_505, _647)), level(0.0)));
    half _617 = _778.z;
    float4 _675 = facet_environment.sample(facet_environmentSmplr, float3(_509), level(_647 * half(4.0)));
    out.fragColor = float4(half4(fma(half4(_675).xyz, _654 * _617, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_570).xyz * (mix(half4(_544).xxx, half4(_544).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_544).y) - half(1.0)))))) * fma(half(-float(max(_654.x, max(_654.y, _654.z)))), _617, half(1.0))), half(1.0)));
    return out;
}

