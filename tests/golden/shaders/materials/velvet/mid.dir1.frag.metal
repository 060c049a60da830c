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
    half3 _549 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    float4 _581 = facet_irradiance.sample(facet_irradianceSmplr, float3(_458), level(0.0));
    half _621 = max(dot(_458, _549), half(9.9999997473787516355514526367188e-05));
    float4 _626 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_621, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _936 = half4(_626);
    half _639 = _936.z;
    half _641 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _639, half(1.0));
    float4 _655 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-_549, _458)), level(params.facet_sheenLod));
    half3 _505 = half4(frame.lightDirection).xyz;
    half _711 = dot(_458, _505);
    half _713 = clamp(_711, half(0.0), half(1.0));
    half _725 = clamp(dot(_458, normalize(_549 + _505)), half(0.0), half(1.0));
    half _794 = half(8192.0) * fma(half(-float(_713)), _621, _713 + _621);
    half _798 = half(1.0) / (half(params.facet_alpha) * _794);
    half3 _758 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_711 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_713), half3(float3(0.0)), half3(float3(1.0)))) * _641) + (half3(float3(params.facet_sheenColor)) * ((((fma(_798, _794, half(2.0)) * pow(max(fma(half(-float(_725)), _725, half(1.0)), half(0.0)), half(0.5) * (_798 * _794))) * half(0.15915493667125701904296875)) * (_713 * (_798 * (half(2048.0) * half(params.facet_alpha))))) * half4(_626).w))) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    half3 _833 = fma(half4(_655).xyz, half3(float3(params.facet_sheenColor)) * _639, (half3(float3(params.facet_diffuseColor)) * half4(_581).xyz) * _641) + _758;
    out.fragColor = float4(half4(_833, half(1.0)));
    return out;
}

