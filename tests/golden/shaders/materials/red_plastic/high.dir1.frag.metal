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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]])
{
    main0_out out = {};
    half3 _522 = normalize(half3(in.v_normal));
    float3 _526 = fast::normalize(in.v_toEye);
    float4 _632 = facet_irradiance.sample(facet_irradianceSmplr, float3(_522), level(0.0));
    half _681 = max(dot(_522, half3(_526)), half(9.9999997473787516355514526367188e-05));
    float4 _714 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_681, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _733 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_526), _522)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _846 = fast::normalize(_526 + frame.lightDirection.xyz);
    half _793 = clamp(dot(_522, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half4 _911 = half4(cross(_522, half3(_846)), half(params.facet_alpha) * clamp(dot(_522, half3(_846)), half(0.0), half(1.0))) * half(64.0);
    half _892 = (half(4096.0) * half(params.facet_alpha)) / dot(_911, _911);
    half _936 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_846)), half(0.0), half(1.0));
    half _939 = _936 * _936;
    half3 _961 = fma(half3(float3(params.facet_diffuseColor)), half4(_632).xyz, half4(_733).xyz * mix(half4(_714).xxx, half4(_714).yyy, half3(float3(params.facet_f0)))) + min(((half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)) + ((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_939 * _939) * _936))) * min(min((_892 * _892) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _793) * _681, _793 + _681, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half4(frame.lightColor).xyz * _793), half3(float3(65504.0)));
    out.fragColor = float4(half4(_961, half(1.0)));
    return out;
}

