#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float anisotropy;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
    packed_float3 facet_f0;
    float facet_alpha;
    float facet_anisotropy;
    float facet_anisotropicBend;
    float2 facet_anisotropicAlpha;
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
    half3 _608 = normalize(half3(in.v_normal));
    float3 _614 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _822 = reflect(-half3(_614), _608);
    float4 _852 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_608, half3(_614)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    half3 _861 = mix(half4(_852).xxx, half4(_852).yyy, half3(float3(params.facet_f0)));
    float4 _871 = facet_environment.sample(facet_environmentSmplr, float3(_822), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _916 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _919 = dot(_916, _916);
    float3 _924 = _916 * rsqrt(fast::max(_919, 9.9999999392252902907785028219223e-09));
    float _928 = _919 * float(frame.punctualLights[0].positionFalloff.w);
    float _933 = fast::clamp(fma(-_928, _928, 1.0), 0.0, 1.0);
    float _952 = fast::clamp(fma(dot(-_924, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1092 = clamp(dot(_822, half3(_924)), half(0.0), half(1.0));
    half _1095 = _1092 * _1092;
    half4 _1546 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1095 * _1095, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1107 = _1546.x;
    float3 _1166 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1169 = dot(_1166, _1166);
    float3 _1174 = _1166 * rsqrt(fast::max(_1169, 9.9999999392252902907785028219223e-09));
    float _1178 = _1169 * float(frame.punctualLights[1].positionFalloff.w);
    float _1183 = fast::clamp(fma(-_1178, _1178, 1.0), 0.0, 1.0);
    float _1202 = fast::clamp(fma(dot(-_1174, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1342 = clamp(dot(_822, half3(_1174)), half(0.0), half(1.0));
    half _1345 = _1342 * _1342;
    half4 _1572 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1345 * _1345, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1357 = _1572.x;
    half3 _1380 = fma(half4(_871).xyz, _861, min((_861 * ((_1107 * _1107) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_933) * half(_933)) / fast::max(_919, 9.9999997473787516355514526367188e-05)) * half(_952)) * half(_952)), float3(65504.0))) * clamp(dot(_608, half3(_924)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_861 * ((_1357 * _1357) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1183) * half(_1183)) / fast::max(_1169, 9.9999997473787516355514526367188e-05)) * half(_1202)) * half(_1202)), float3(65504.0))) * clamp(dot(_608, half3(_1174)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1380, half(1.0)));
    return out;
}

