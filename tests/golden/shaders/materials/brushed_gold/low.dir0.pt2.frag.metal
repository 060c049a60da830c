#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float facet_perceptualRoughness;
    char _m3_pad[12];
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
    float3 v_worldPosition [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _543 = normalize(half3(in.v_normal));
    float3 _559 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _719 = reflect(-half3(_559), _543);
    float4 _755 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_543, half3(_559)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _784 = facet_environment.sample(facet_environmentSmplr, float3(_719), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _734 = mix(half4(_755).xxx, half4(_755).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_755).y) - half(1.0))));
    float3 _829 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _832 = dot(_829, _829);
    float3 _837 = _829 * rsqrt(fast::max(_832, 9.9999999392252902907785028219223e-09));
    float _841 = _832 * float(frame.punctualLights[0].positionFalloff.w);
    float _846 = fast::clamp(fma(-_841, _841, 1.0), 0.0, 1.0);
    float _865 = fast::clamp(fma(dot(-_837, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _997 = clamp(dot(_719, half3(_837)), half(0.0), half(1.0));
    half _1000 = _997 * _997;
    half4 _1415 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1000 * _1000, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1012 = _1415.x;
    float3 _1057 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1060 = dot(_1057, _1057);
    float3 _1065 = _1057 * rsqrt(fast::max(_1060, 9.9999999392252902907785028219223e-09));
    float _1069 = _1060 * float(frame.punctualLights[1].positionFalloff.w);
    float _1074 = fast::clamp(fma(-_1069, _1069, 1.0), 0.0, 1.0);
    float _1093 = fast::clamp(fma(dot(-_1065, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1225 = clamp(dot(_719, half3(_1065)), half(0.0), half(1.0));
    half _1228 = _1225 * _1225;
    half4 _1441 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1228 * _1228, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1240 = _1441.x;
    half3 _1249 = fma(half4(_784).xyz, _734, min((_734 * ((_1012 * _1012) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_846) * half(_846)) / fast::max(_832, 9.9999997473787516355514526367188e-05)) * half(_865)) * half(_865)), float3(65504.0))) * clamp(dot(_543, half3(_837)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_734 * ((_1240 * _1240) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1074) * half(_1074)) / fast::max(_1060, 9.9999997473787516355514526367188e-05)) * half(_1093)) * half(_1093)), float3(65504.0))) * clamp(dot(_543, half3(_1065)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1249, half(1.0)));
    return out;
}

