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
    char _m8_pad[12];
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
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
    half3 _385 = normalize(half3(in.v_normal));
    float3 _389 = fast::normalize(in.v_toEye);
    half _527 = max(dot(_385, half3(_389)), half(9.9999997473787516355514526367188e-05));
    float4 _532 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_527, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _788 = half4(_532);
    half _545 = _788.z;
    float4 _561 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_389), _385)), level(params.facet_sheenLod));
    half3 _434 = half4(frame.lightDirection).xyz;
    half _616 = clamp(dot(_385, _434), half(0.0), half(1.0));
    half _628 = clamp(dot(_385, normalize(half3(_389) + _434)), half(0.0), half(1.0));
    half _673 = half(8192.0) * fma(half(-float(_616)), _527, _616 + _527);
    half _677 = half(1.0) / (half(params.facet_alpha) * _673);
    half3 _706 = fma(half4(_561).xyz, half3(float3(params.facet_sheenColor)) * _545, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _545, half(1.0))) + min((half3(float3(params.facet_sheenColor)) * ((((fma(_677, _673, half(2.0)) * pow(max(fma(half(-float(_628)), _628, half(1.0)), half(0.0)), half(0.5) * (_677 * _673))) * half(0.15915493667125701904296875)) * (_616 * (_677 * (half(2048.0) * half(params.facet_alpha))))) * half4(_532).w)) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    out.fragColor = float4(half4(_706, half(1.0)));
    return out;
}

