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
    half3 _377 = normalize(half3(in.v_normal));
    float3 _381 = fast::normalize(in.v_toEye);
    half _517 = max(dot(_377, half3(_381)), half(9.9999997473787516355514526367188e-05));
    float4 _522 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_517, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _568 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _782 = half4(_522);
    half _535 = _782.z;
    float4 _575 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_381), _377)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _426 = half4(frame.lightDirection).xyz;
    half _601 = clamp(dot(_377, _426), half(0.0), half(1.0));
    half _615 = clamp(dot(_377, normalize(half3(_381) + _426)), half(0.0), half(1.0));
    half3 _696 = fma(half4(_575).xyz, _568 * _535, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_568.x, max(_568.y, _568.z)))), _535, half(1.0))) + min((_568 * (((((half(2.0) + (half(1.0) / half(params.facet_alpha))) * pow(max(fma(half(-float(_615)), _615, half(1.0)), half(0.0)), half(0.5) / half(params.facet_alpha))) * half(0.15915493667125701904296875)) * (_601 / (half(4.0) * fma(half(-float(_601)), _517, _601 + _517)))) * half4(_522).w)) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    out.fragColor = float4(half4(_696, half(1.0)));
    return out;
}

