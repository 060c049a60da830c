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
    half3 _686 = normalize(half3(in.v_normal));
    float3 _690 = fast::normalize(in.v_toEye);
    half _941 = max(dot(_686, half3(_690)), half(9.9999997473787516355514526367188e-05));
    float4 _980 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_941, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _999 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_980).y) - half(1.0)));
    float4 _1009 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_690), _686)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1125 = fast::normalize(_690 + frame.lightDirection.xyz);
    half _1069 = clamp(dot(_686, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half4 _1190 = half4(cross(_686, half3(_1125)), half(params.facet_alpha) * clamp(dot(_686, half3(_1125)), half(0.0), half(1.0))) * half(64.0);
    half _1171 = (half(4096.0) * half(params.facet_alpha)) / dot(_1190, _1190);
    half _1201 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1207 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1235 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1125)), half(0.0), half(1.0));
    half _1238 = _1235 * _1235;
    half4 _1283 = half4(fma(half4(_1009).xyz, mix(half4(_980).xxx, half4(_980).yyy, half3(float3(params.facet_f0))) * _999, min((((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1238 * _1238) * _1235))) * min(min((_1171 * _1171) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1069, sqrt(fma(_941 * _941, _1207, _1201)), _941 * sqrt(fma(_1069 * _1069, _1207, _1201))), half(65504.0)), half(65504.0))) * _999) * (half4(frame.lightColor).xyz * _1069), half3(float3(65504.0)))), half(1.0));
    out.fragColor = float4(_1283);
    return out;
}

