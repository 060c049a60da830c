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
    half3 _667 = normalize(half3(in.v_normal));
    float3 _671 = fast::normalize(in.v_toEye);
    half _922 = max(dot(_667, half3(_671)), half(9.9999997473787516355514526367188e-05));
    float4 _961 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_922, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _980 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_961).y) - half(1.0)));
    float4 _990 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_671), _667)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1106 = fast::normalize(_671 + frame.lightDirection.xyz);
    half _1050 = clamp(dot(_667, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1146 = cross(_667, half3(_1106));
    half _1149 = clamp(dot(_667, half3(_1106)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1158 = half(params.facet_alpha) / fma(_1149, _1149, dot(_1146, _1146));
    half _1172 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1178 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1206 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1106)), half(0.0), half(1.0));
    half _1209 = _1206 * _1206;
    half3 _1239 = fma(half4(_990).xyz, mix(half4(_961).xxx, half4(_961).yyy, half3(float3(params.facet_f0))) * _980, min((((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1209 * _1209) * _1206))) * min(min((_1158 * _1158) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1050, sqrt(fma(_922 * _922, _1178, _1172)), _922 * sqrt(fma(_1050 * _1050, _1178, _1172))), half(65504.0)), half(65504.0))) * _980) * (half4(frame.lightColor).xyz * _1050), half3(float3(65504.0))));
    out.fragColor = float4(half4(_1239, half(1.0)));
    return out;
}

