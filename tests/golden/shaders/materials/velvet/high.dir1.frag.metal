#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    half3 _548 = normalize(half3(in.v_normal));
    float3 _552 = fast::normalize(in.v_toEye);
    half _672 = _548.y;
    half _677 = _548.z;
    half _682 = _548.x;
    half3 _750 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _672)) + (half4(frame.sh[2]).xyz * _677)) + (half4(frame.sh[3]).xyz * _682)) + (((((half4(frame.sh[4]).xyz * (_682 * _672)) + (half4(frame.sh[5]).xyz * (_672 * _677))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _677, _677, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_682 * _677))) + (half4(frame.sh[8]).xyz * fma(_682, _682, half(-float(_672 * _672))))), half3(float3(0.0)));
    half _790 = max(dot(_548, half3(_552)), half(9.9999997473787516355514526367188e-05));
    float4 _795 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_790, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _841 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1147 = half4(_795);
    half _808 = _1147.z;
    half _810 = fma(half(-float(max(_841.x, max(_841.y, _841.z)))), _808, half(1.0));
    float4 _848 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_552), _548)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _875 = dot(_548, half3(frame.lightDirection.xyz));
    half _877 = clamp(_875, half(0.0), half(1.0));
    half _891 = clamp(dot(_548, half3(fast::normalize(_552 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half3 _928 = ((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_875 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_877), half3(float3(0.0)), half3(float3(1.0)))) * _810) + (_841 * (((((half(2.0) + (half(1.0) / half(params.facet_alpha))) * pow(max(fma(half(-float(_891)), _891, half(1.0)), half(0.0)), half(0.5) / half(params.facet_alpha))) * half(0.15915493667125701904296875)) * (_877 / (half(4.0) * fma(half(-float(_877)), _790, _877 + _790)))) * half4(_795).w))) * half4(frame.lightColor).xyz;
    out.fragColor = float4(half4(fma(half4(_848).xyz, _841 * _808, (half3(float3(params.facet_diffuseColor)) * _750) * _810) + min(_928, half3(float3(65504.0))), half(1.0)));
    return out;
}

