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
    half3 _682 = normalize(half3(in.v_normal));
    float3 _686 = fast::normalize(in.v_toEye);
    half _937 = max(dot(_682, half3(_686)), half(9.9999997473787516355514526367188e-05));
    float4 _976 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_937, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _995 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_976).y) - half(1.0)));
    float4 _1002 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_686), _682)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1118 = fast::normalize(_686 + frame.lightDirection.xyz);
    half _1062 = clamp(dot(_682, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half4 _1183 = half4(cross(_682, half3(_1118)), half(params.facet_alpha) * clamp(dot(_682, half3(_1118)), half(0.0), half(1.0))) * half(64.0);
    half _1164 = (half(4096.0) * half(params.facet_alpha)) / dot(_1183, _1183);
    half _1194 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1200 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1228 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1118)), half(0.0), half(1.0));
    half _1231 = _1228 * _1228;
    half4 _1276 = half4(fma(half4(_1002).xyz, mix(half4(_976).xxx, half4(_976).yyy, half3(float3(params.facet_f0))) * _995, min((((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1231 * _1231) * _1228))) * min(min((_1164 * _1164) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1062, sqrt(fma(_937 * _937, _1200, _1194)), _937 * sqrt(fma(_1062 * _1062, _1200, _1194))), half(65504.0)), half(65504.0))) * _995) * (half4(frame.lightColor).xyz * _1062), half3(float3(65504.0)))), half(1.0));
    out.fragColor = float4(_1276);
    return out;
}

