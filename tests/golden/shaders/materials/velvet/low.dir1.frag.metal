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
    half3 _406 = normalize(half3(in.v_normal));
    float3 _410 = fast::normalize(in.v_toEye);
    half _550 = max(dot(_406, half3(_410)), half(9.9999997473787516355514526367188e-05));
    float4 _555 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_550, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _609 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _826 = half4(_555);
    half _568 = _826.z;
    float4 _630 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_410), _406)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _455 = half4(frame.lightDirection).xyz;
    half _652 = clamp(dot(_406, _455), half(0.0), half(1.0));
    half _664 = clamp(dot(_406, normalize(half3(_410) + _455)), half(0.0), half(1.0));
    half _709 = half(8192.0) * fma(half(-float(_652)), _550, _652 + _550);
    half _713 = half(1.0) / (half(params.facet_alpha) * _709);
    half3 _742 = fma(half4(_630).xyz, _609 * _568, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_609.x, max(_609.y, _609.z)))), _568, half(1.0))) + min((_609 * ((((fma(_713, _709, half(2.0)) * pow(max(fma(half(-float(_664)), _664, half(1.0)), half(0.0)), half(0.5) * (_713 * _709))) * half(0.15915493667125701904296875)) * (_652 * (_713 * (half(2048.0) * half(params.facet_alpha))))) * half4(_555).w)) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    out.fragColor = float4(half4(_742, half(1.0)));
    return out;
}

