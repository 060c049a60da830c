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
    half3 _465 = normalize(half3(in.v_normal));
    float3 _469 = fast::normalize(in.v_toEye);
    float4 _643 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_465, half3(_469)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _662 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_469), _465)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _517 = half4(frame.lightDirection).xyz;
    half3 _766 = normalize(half3(_469) + _517);
    half _728 = clamp(dot(_517, _766), half(0.0), half(1.0));
    half4 _818 = half4(cross(_465, _766), half(params.facet_alpha) * clamp(dot(_465, _766), half(0.0), half(1.0))) * half(64.0);
    half _837 = (half(12.56637096405029296875) * max(_728 * _728, half(0.1500000059604644775390625))) * fma(half(-0.3125), half(params.facet_alpha), half(1.00820004940032958984375));
    half _842 = half(params.facet_alpha) / ((dot(_818, _818) * half(0.000244140625)) * _837);
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_662).xyz * mix(half4(_643).xxx, half4(_643).yyy, half3(float3(params.facet_f0)))) + min((half3(float3(params.facet_f0)) * min((_842 * _842) * _837, half(65504.0))) * (half4(frame.lightColor).xyz * clamp(dot(_465, _517), half(0.0), half(1.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

