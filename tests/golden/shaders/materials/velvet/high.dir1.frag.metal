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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    half3 _458 = normalize(half3(in.v_normal));
    half3 _548 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    float4 _580 = facet_irradiance.sample(facet_irradianceSmplr, float3(_458), level(0.0));
    half _620 = max(dot(_458, _548), half(9.9999997473787516355514526367188e-05));
    float4 _625 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_620, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _935 = half4(_625);
    half _638 = _935.z;
    half _640 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _638, half(1.0));
    float4 _654 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-_548, _458)), level(params.facet_sheenLod));
    half3 _505 = half4(frame.lightDirection).xyz;
    half _710 = dot(_458, _505);
    half _712 = clamp(_710, half(0.0), half(1.0));
    half _724 = clamp(dot(_458, normalize(_548 + _505)), half(0.0), half(1.0));
    half _793 = half(8192.0) * fma(half(-float(_712)), _620, _712 + _620);
    half _797 = half(1.0) / (half(params.facet_alpha) * _793);
    half3 _757 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_710 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_712), half3(float3(0.0)), half3(float3(1.0)))) * _640) + (half3(float3(params.facet_sheenColor)) * ((((fma(_797, _793, half(2.0)) * pow(max(fma(half(-float(_724)), _724, half(1.0)), half(0.0)), half(0.5) * (_797 * _793))) * half(0.15915493667125701904296875)) * (_712 * (_797 * (half(2048.0) * half(params.facet_alpha))))) * half4(_625).w))) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    half3 _832 = fma(half4(_654).xyz, half3(float3(params.facet_sheenColor)) * _638, (half3(float3(params.facet_diffuseColor)) * half4(_580).xyz) * _640) + _757;
    out.fragColor = float4(half4(_832, half(1.0)));
    return out;
}

