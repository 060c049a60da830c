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
    half3 _663 = normalize(half3(in.v_normal));
    float3 _667 = fast::normalize(in.v_toEye);
    half _918 = max(dot(_663, half3(_667)), half(9.9999997473787516355514526367188e-05));
    float4 _957 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_918, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _976 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_957).y) - half(1.0)));
    float4 _983 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_667), _663)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1099 = fast::normalize(_667 + frame.lightDirection.xyz);
    half _1043 = clamp(dot(_663, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1139 = cross(_663, half3(_1099));
    half _1142 = clamp(dot(_663, half3(_1099)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1151 = half(params.facet_alpha) / fma(_1142, _1142, dot(_1139, _1139));
    half _1165 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1171 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1199 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1099)), half(0.0), half(1.0));
    half _1202 = _1199 * _1199;
    half4 _1248 = half4(fma(half4(_983).xyz, mix(half4(_957).xxx, half4(_957).yyy, half3(float3(params.facet_f0))) * _976, min((((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1202 * _1202) * _1199))) * min(min((_1151 * _1151) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1043, sqrt(fma(_918 * _918, _1171, _1165)), _918 * sqrt(fma(_1043 * _1043, _1171, _1165))), half(65504.0)), half(65504.0))) * _976) * (half4(frame.lightColor).xyz * _1043), half3(float3(65504.0)))), half(1.0));
    out.fragColor = float4(_1248);
    return out;
}

