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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _574 = normalize(half3(in.v_normal));
    float3 _578 = fast::normalize(in.v_toEye);
    half _698 = _574.y;
    half _703 = _574.z;
    half _708 = _574.x;
    half3 _776 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _698)) + (half4(frame.sh[2]).xyz * _703)) + (half4(frame.sh[3]).xyz * _708)) + (((((half4(frame.sh[4]).xyz * (_708 * _698)) + (half4(frame.sh[5]).xyz * (_698 * _703))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _703, _703, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_708 * _703))) + (half4(frame.sh[8]).xyz * fma(_708, _708, half(-float(_698 * _698))))), half3(float3(0.0)));
    half _817 = max(dot(_574, half3(_578)), half(9.9999997473787516355514526367188e-05));
    float4 _822 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_817, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _876 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1183 = half4(_822);
    half _835 = _1183.z;
    half _837 = fma(half(-float(max(_876.x, max(_876.y, _876.z)))), _835, half(1.0));
    float4 _895 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_578), _574)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _918 = dot(_574, half3(frame.lightDirection.xyz));
    half _920 = clamp(_918, half(0.0), half(1.0));
    half _932 = clamp(dot(_574, half3(fast::normalize(_578 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half _1003 = half(8192.0) * fma(half(-float(_920)), _817, _920 + _817);
    half _1007 = half(1.0) / (half(params.facet_alpha) * _1003);
    half3 _965 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_918 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_920), half3(float3(0.0)), half3(float3(1.0)))) * _837) + (_876 * ((((fma(_1007, _1003, half(2.0)) * pow(max(fma(half(-float(_932)), _932, half(1.0)), half(0.0)), half(0.5) * (_1007 * _1003))) * half(0.15915493667125701904296875)) * (_920 * (_1007 * (half(2048.0) * half(params.facet_alpha))))) * half4(_822).w))) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_895).xyz, _876 * _835, (half3(float3(params.facet_diffuseColor)) * _776) * _837) + _965, half(1.0)));
    return out;
}

