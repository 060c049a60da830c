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
    half3 _669 = normalize(half3(in.v_normal));
    float3 _673 = fast::normalize(in.v_toEye);
    half _924 = max(dot(_669, half3(_673)), half(9.9999997473787516355514526367188e-05));
    float4 _963 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_924, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _982 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_963).y) - half(1.0)));
    float4 _994 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_673), _669)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1110 = fast::normalize(_673 + frame.lightDirection.xyz);
    half _1054 = clamp(dot(_669, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1150 = cross(_669, half3(_1110));
    half _1153 = clamp(dot(_669, half3(_1110)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1162 = half(params.facet_alpha) / fma(_1153, _1153, dot(_1150, _1150));
    half _1176 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1182 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1210 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1110)), half(0.0), half(1.0));
    half _1213 = _1210 * _1210;
    half3 _1243 = fma(half4(_994).xyz, mix(half4(_963).xxx, half4(_963).yyy, half3(float3(params.facet_f0))) * _982, min((((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1213 * _1213) * _1210))) * min(min((_1162 * _1162) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1054, sqrt(fma(_924 * _924, _1182, _1176)), _924 * sqrt(fma(_1054 * _1054, _1182, _1176))), half(65504.0)), half(65504.0))) * _982) * (half4(frame.lightColor).xyz * _1054), half3(float3(65504.0))));
    out.fragColor = float4(half4(_1243, half(1.0)));
    return out;
}

