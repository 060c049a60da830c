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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _354 = normalize(half3(in.v_normal));
    float3 _358 = fast::normalize(in.v_toEye);
    half _494 = max(dot(_354, half3(_358)), half(9.9999997473787516355514526367188e-05));
    float4 _499 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_494, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _527 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_358), _354)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _535 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half3 _405 = half4(frame.lightDirection).xyz;
    half _575 = clamp(dot(_354, _405), half(0.0), half(1.0));
    half _579 = clamp(dot(_354, normalize(half3(_358) + _405)), half(0.0), half(1.0));
    float4 _772 = float4(half4(fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_527).xyz * (_535 * half4(_499).z)) + min((_535 * (((((half(2.0) + (half(1.0) / half(params.facet_alpha))) * pow(max(fma(half(-float(_579)), _579, half(1.0)), half(0.0)), half(0.5) / half(params.facet_alpha))) * half(0.15915493667125701904296875)) * (_575 / (half(4.0) * fma(half(-float(_575)), _494, _575 + _494)))) * half4(_499).w)) * half4(frame.lightColor).xyz, half3(float3(65504.0))), half(1.0)));
    out.fragColor = _772;
    return out;
}

