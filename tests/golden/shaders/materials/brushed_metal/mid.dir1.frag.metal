#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float anisotropy;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
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
    half3 _465 = normalize(half3(in.v_normal));
    float3 _469 = fast::normalize(in.v_toEye);
    half _621 = max(dot(_465, half3(_469)), half(9.9999997473787516355514526367188e-05));
    float4 _660 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_621, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _679 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_660).y) - half(1.0)));
    float4 _689 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_469), _465)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _516 = half4(frame.lightDirection).xyz;
    half3 _796 = normalize(half3(_469) + _516);
    half _747 = clamp(dot(_465, _516), half(0.0), half(1.0));
    half3 _823 = cross(_465, _796);
    half _826 = clamp(dot(_465, _796), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _843 = max(mix((half(2.0) * _747) * _621, _747 + _621, half(params.facet_alpha)), half(0.000244140625));
    half _850 = (half(1024.0) * half(params.facet_alpha)) / (fma(_826, _826, dot(_823, _823)) * (half(6433.98193359375) * _843));
    out.fragColor = float4(half4(fma(half4(_689).xyz, mix(half4(_660).xxx, half4(_660).yyy, half3(float3(params.facet_f0))) * _679, min(((half3(float3(params.facet_f0)) * min(_850 * (_850 * (half(6.283185482025146484375) * _843)), half(65504.0))) * _679) * (half4(frame.lightColor).xyz * _747), half3(float3(65504.0)))), half(1.0)));
    return out;
}

