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
    half3 _404 = normalize(half3(in.v_normal));
    float3 _408 = fast::normalize(in.v_toEye);
    half _548 = max(dot(_404, half3(_408)), half(9.9999997473787516355514526367188e-05));
    float4 _553 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_548, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _607 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _822 = half4(_553);
    half _566 = _822.z;
    float4 _626 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_408), _404)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _453 = half4(frame.lightDirection).xyz;
    half _648 = clamp(dot(_404, _453), half(0.0), half(1.0));
    half _660 = clamp(dot(_404, normalize(half3(_408) + _453)), half(0.0), half(1.0));
    half _705 = half(8192.0) * fma(half(-float(_648)), _548, _648 + _548);
    half _709 = half(1.0) / (half(params.facet_alpha) * _705);
    half3 _738 = fma(half4(_626).xyz, _607 * _566, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_607.x, max(_607.y, _607.z)))), _566, half(1.0))) + min((_607 * ((((fma(_709, _705, half(2.0)) * pow(max(fma(half(-float(_660)), _660, half(1.0)), half(0.0)), half(0.5) * (_709 * _705))) * half(0.15915493667125701904296875)) * (_648 * (_709 * (half(2048.0) * half(params.facet_alpha))))) * half4(_553).w)) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    out.fragColor = float4(half4(_738, half(1.0)));
    return out;
}

