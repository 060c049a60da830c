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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    half3 _580 = normalize(half3(in.v_normal));
    float3 _584 = fast::normalize(in.v_toEye);
    half _764 = max(dot(_580, half3(_584)), half(9.9999997473787516355514526367188e-05));
    float4 _806 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_764, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _825 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_806).y) - half(1.0)));
    float4 _782 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_584), _580)), level(params.facet_environmentLod));
    half _881 = clamp(dot(_580, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    float3 _940 = fast::normalize(_584 + frame.lightDirection.xyz);
    half4 _1005 = half4(cross(_580, half3(_940)), half(params.facet_alpha) * clamp(dot(_580, half3(_940)), half(0.0), half(1.0))) * half(64.0);
    half _986 = (half(4096.0) * half(params.facet_alpha)) / dot(_1005, _1005);
    half _1030 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_940)), half(0.0), half(1.0));
    half _1033 = _1030 * _1030;
    float4 _1180 = float4(half4(fma(half4(_782).xyz, mix(half4(_806).xxx, half4(_806).yyy, half3(float3(params.facet_f0))) * _825, min((((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1033 * _1033) * _1030))) * min(min((_986 * _986) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _881) * _764, _881 + _764, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * _825) * (half4(frame.lightColor).xyz * _881), half3(float3(65504.0)))), half(1.0)));
    out.fragColor = _1180;
    return out;
}

