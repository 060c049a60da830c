#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float facet_perceptualRoughness;
    char _m3_pad[12];
    packed_float3 facet_f0;
    float facet_alpha;
};

struct PunctualLightData
{
    float4 positionFalloff;
    float4 colorIntensity;
    float4 direction;
    float4 spotScaleOffset;
};

struct FrameUniforms
{
    float4x4 viewProjection;
    float4 cameraPosition;
    float4 lightDirection;
    float4 lightColor;
    float4 ambient;
    PunctualLightData punctualLights[4];
    float4 sh[9];
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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _457 = normalize(half3(in.v_normal));
    float3 _461 = fast::normalize(in.v_toEye);
    half _608 = max(dot(_457, half3(_461)), half(9.9999997473787516355514526367188e-05));
    float4 _647 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_608, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _666 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_647).y) - half(1.0)));
    float4 _676 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_461), _457)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _508 = half4(frame.lightDirection).xyz;
    half3 _783 = normalize(half3(_461) + _508);
    half _734 = clamp(dot(_457, _508), half(0.0), half(1.0));
    half3 _810 = cross(_457, _783);
    half _813 = clamp(dot(_457, _783), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _830 = max(mix((half(2.0) * _734) * _608, _734 + _608, half(params.facet_alpha)), half(0.000244140625));
    half _837 = (half(1024.0) * half(params.facet_alpha)) / (fma(_813, _813, dot(_810, _810)) * (half(6433.98193359375) * _830));
    out.fragColor = float4(half4(fma(half4(_676).xyz, mix(half4(_647).xxx, half4(_647).yyy, half3(float3(params.facet_f0))) * _666, min(((half3(float3(params.facet_f0)) * min(_837 * (_837 * (half(6.283185482025146484375) * _830)), half(65504.0))) * _666) * (half4(frame.lightColor).xyz * _734), half3(float3(65504.0)))), half(1.0)));
    return out;
}

