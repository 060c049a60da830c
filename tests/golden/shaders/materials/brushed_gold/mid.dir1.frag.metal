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
    half3 _595 = normalize(half3(in.v_normal));
    float3 _599 = fast::normalize(in.v_toEye);
    half _781 = max(dot(_595, half3(_599)), half(9.9999997473787516355514526367188e-05));
    float4 _820 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_781, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _839 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_820).y) - half(1.0)));
    float4 _849 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_599), _595)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _965 = fast::normalize(_599 + frame.lightDirection.xyz);
    half _909 = clamp(dot(_595, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half4 _1030 = half4(cross(_595, half3(_965)), half(params.facet_alpha) * clamp(dot(_595, half3(_965)), half(0.0), half(1.0))) * half(64.0);
    half _1011 = (half(4096.0) * half(params.facet_alpha)) / dot(_1030, _1030);
    half _1055 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_965)), half(0.0), half(1.0));
    half _1058 = _1055 * _1055;
    half3 _1088 = fma(half4(_849).xyz, mix(half4(_820).xxx, half4(_820).yyy, half3(float3(params.facet_f0))) * _839, min((((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1058 * _1058) * _1055))) * min(min((_1011 * _1011) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _909) * _781, _909 + _781, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * _839) * (half4(frame.lightColor).xyz * _909), half3(float3(65504.0))));
    out.fragColor = float4(half4(_1088, half(1.0)));
    return out;
}

