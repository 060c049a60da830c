#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _462 = normalize(half3(in.v_normal));
    float3 _466 = fast::normalize(in.v_toEye);
    half _607 = max(dot(_462, half3(_466)), half(9.9999997473787516355514526367188e-05));
    float4 _640 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_607, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _656 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_466), _462)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _761 = fast::normalize(_466 + frame.lightDirection.xyz);
    half _714 = clamp(dot(_462, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _801 = cross(_462, half3(_761));
    half _804 = clamp(dot(_462, half3(_761)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _813 = half(params.facet_alpha) / fma(_804, _804, dot(_801, _801));
    half _841 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_761)), half(0.0), half(1.0));
    half _844 = _841 * _841;
    half3 _860 = fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_656).xyz * mix(half4(_640).xxx, half4(_640).yyy, half3(float3(params.facet_f0)))) + min(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_844 * _844) * _841))) * min(min((_813 * _813) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _714) * _607, _714 + _607, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * (half4(frame.lightColor).xyz * _714), half3(float3(65504.0)));
    out.fragColor = float4(half4(_860, half(1.0)));
    return out;
}

