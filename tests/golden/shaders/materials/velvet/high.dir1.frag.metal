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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]])
{
    main0_out out = {};
    half3 _445 = normalize(half3(in.v_normal));
    float3 _449 = fast::normalize(in.v_toEye);
    float4 _556 = facet_irradiance.sample(facet_irradianceSmplr, float3(_445), level(0.0));
    half _596 = max(dot(_445, half3(_449)), half(9.9999997473787516355514526367188e-05));
    float4 _601 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_596, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _910 = half4(_601);
    half _614 = _910.z;
    half _616 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _614, half(1.0));
    float4 _630 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_449), _445)), level(params.facet_sheenLod));
    half _686 = dot(_445, half3(frame.lightDirection.xyz));
    half _688 = clamp(_686, half(0.0), half(1.0));
    half _700 = clamp(dot(_445, half3(fast::normalize(_449 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half _771 = half(8192.0) * fma(half(-float(_688)), _596, _688 + _596);
    half _775 = half(1.0) / (half(params.facet_alpha) * _771);
    half3 _733 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_686 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_688), half3(float3(0.0)), half3(float3(1.0)))) * _616) + (half3(float3(params.facet_sheenColor)) * ((((fma(_775, _771, half(2.0)) * pow(max(fma(half(-float(_700)), _700, half(1.0)), half(0.0)), half(0.5) * (_775 * _771))) * half(0.15915493667125701904296875)) * (_688 * (_775 * (half(2048.0) * half(params.facet_alpha))))) * half4(_601).w))) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_630).xyz, half3(float3(params.facet_sheenColor)) * _614, (half3(float3(params.facet_diffuseColor)) * half4(_556).xyz) * _616) + _733, half(1.0)));
    return out;
}

