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
    half3 _467 = normalize(half3(in.v_normal));
    float3 _471 = fast::normalize(in.v_toEye);
    half _623 = max(dot(_467, half3(_471)), half(9.9999997473787516355514526367188e-05));
    float4 _662 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_623, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _681 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_662).y) - half(1.0)));
    float4 _693 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_471), _467)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _518 = half4(frame.lightDirection).xyz;
    half3 _800 = normalize(half3(_471) + _518);
    half _751 = clamp(dot(_467, _518), half(0.0), half(1.0));
    half3 _827 = cross(_467, _800);
    half _830 = clamp(dot(_467, _800), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _847 = max(mix((half(2.0) * _751) * _623, _751 + _623, half(params.facet_alpha)), half(0.000244140625));
    half _854 = (half(1024.0) * half(params.facet_alpha)) / (fma(_830, _830, dot(_827, _827)) * (half(6433.98193359375) * _847));
    out.fragColor = float4(half4(fma(half4(_693).xyz, mix(half4(_662).xxx, half4(_662).yyy, half3(float3(params.facet_f0))) * _681, min(((half3(float3(params.facet_f0)) * min(_854 * (_854 * (half(6.283185482025146484375) * _847)), half(65504.0))) * _681) * (half4(frame.lightColor).xyz * _751), half3(float3(65504.0)))), half(1.0)));
    return out;
}

