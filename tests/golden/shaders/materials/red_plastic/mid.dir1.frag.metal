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
    half3 _437 = normalize(half3(in.v_normal));
    float3 _441 = fast::normalize(in.v_toEye);
    float4 _615 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_437, half3(_441)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _631 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_441), _437)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _489 = half4(frame.lightDirection).xyz;
    half3 _735 = normalize(half3(_441) + _489);
    half _697 = clamp(dot(_489, _735), half(0.0), half(1.0));
    half3 _763 = cross(_437, _735);
    half _766 = clamp(dot(_437, _735), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _792 = (half(12.56637096405029296875) * max(_697 * _697, half(0.1500000059604644775390625))) * fma(half(-0.3125), half(params.facet_alpha), half(1.00820004940032958984375));
    half _797 = half(params.facet_alpha) / (fma(_766, _766, dot(_763, _763)) * _792);
    half3 _808 = fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_631).xyz * mix(half4(_615).xxx, half4(_615).yyy, half3(float3(params.facet_f0)))) + min((half3(float3(params.facet_f0)) * min((_797 * _797) * _792, half(65504.0))) * (half4(frame.lightColor).xyz * clamp(dot(_437, _489), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_808, half(1.0)));
    return out;
}

