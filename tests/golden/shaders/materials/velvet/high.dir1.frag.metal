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
    half3 _523 = normalize(half3(in.v_normal));
    float3 _527 = fast::normalize(in.v_toEye);
    half _649 = _523.y;
    half _654 = _523.z;
    half _659 = _523.x;
    half3 _727 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _649)) + (half4(frame.sh[2]).xyz * _654)) + (half4(frame.sh[3]).xyz * _659)) + (((((half4(frame.sh[4]).xyz * (_659 * _649)) + (half4(frame.sh[5]).xyz * (_649 * _654))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _654, _654, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_659 * _654))) + (half4(frame.sh[8]).xyz * fma(_659, _659, half(-float(_649 * _649))))), half3(float3(0.0)));
    half _765 = max(dot(_523, half3(_527)), half(9.9999997473787516355514526367188e-05));
    float4 _770 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_765, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _798 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_527), _523)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _806 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half _847 = dot(_523, half3(frame.lightDirection.xyz));
    half _849 = clamp(_847, half(0.0), half(1.0));
    half _853 = clamp(dot(_523, half3(fast::normalize(_527 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half3 _889 = min(fma(half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_847 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0))), clamp(half3(float3(params.subsurface)) + half3(_849), half3(float3(0.0)), half3(float3(1.0))), _806 * (((((half(2.0) + (half(1.0) / half(params.facet_alpha))) * pow(max(fma(half(-float(_853)), _853, half(1.0)), half(0.0)), half(0.5) / half(params.facet_alpha))) * half(0.15915493667125701904296875)) * (_849 / (half(4.0) * fma(half(-float(_849)), _765, _849 + _765)))) * half4(_770).w)) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), _727, half4(_798).xyz * (_806 * half4(_770).z)) + _889, half(1.0)));
    return out;
}

