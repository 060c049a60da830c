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
    float facet_anisotropy;
    float facet_anisotropicBend;
    float2 facet_anisotropicAlpha;
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
    half3 _484 = normalize(half3(in.v_normal));
    float3 _488 = fast::normalize(in.v_toEye);
    half _640 = max(dot(_484, half3(_488)), half(9.9999997473787516355514526367188e-05));
    float4 _679 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_640, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _698 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_679).y) - half(1.0)));
    float4 _708 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_488), _484)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _535 = half4(frame.lightDirection).xyz;
    half3 _815 = normalize(half3(_488) + _535);
    half _766 = clamp(dot(_484, _535), half(0.0), half(1.0));
    half4 _884 = half4(cross(_484, _815), half(params.facet_alpha) * clamp(dot(_484, _815), half(0.0), half(1.0))) * half(64.0);
    half _861 = half(6.283185482025146484375) * max(mix((half(2.0) * _766) * _640, _766 + _640, half(params.facet_alpha)), half(0.000244140625));
    half _863 = (half(4096.0) * half(params.facet_alpha)) / (dot(_884, _884) * _861);
    out.fragColor = float4(half4(fma(half4(_708).xyz, mix(half4(_679).xxx, half4(_679).yyy, half3(float3(params.facet_f0))) * _698, min(((half3(float3(params.facet_f0)) * min(_863 * (_863 * _861), half(65504.0))) * _698) * (half4(frame.lightColor).xyz * _766), half3(float3(65504.0)))), half(1.0)));
    return out;
}

