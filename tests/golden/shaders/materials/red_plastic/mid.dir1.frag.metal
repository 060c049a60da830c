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
    half3 _478 = normalize(half3(in.v_normal));
    half3 _574 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    float4 _667 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_478, _574), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _686 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-_574, _478)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _531 = half4(frame.lightDirection).xyz;
    half3 _790 = normalize(_574 + _531);
    half _752 = clamp(dot(_531, _790), half(0.0), half(1.0));
    half4 _842 = half4(cross(_478, _790), half(params.facet_alpha) * clamp(dot(_478, _790), half(0.0), half(1.0))) * half(64.0);
    half _861 = (half(12.56637096405029296875) * max(_752 * _752, half(0.1500000059604644775390625))) * fma(half(-0.3125), half(params.facet_alpha), half(1.00820004940032958984375));
    half _866 = half(params.facet_alpha) / ((dot(_842, _842) * half(0.000244140625)) * _861);
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_686).xyz * mix(half4(_667).xxx, half4(_667).yyy, half3(float3(params.facet_f0)))) + min((half3(float3(params.facet_f0)) * min((_866 * _866) * _861, half(65504.0))) * (half4(frame.lightColor).xyz * clamp(dot(_478, _531), half(0.0), half(1.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

