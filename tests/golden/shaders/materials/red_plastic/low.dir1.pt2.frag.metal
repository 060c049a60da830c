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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _501 = normalize(half3(in.v_normal));
    float3 _517 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _689 = reflect(-half3(_517), _501);
    float4 _722 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_501, half3(_517)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    half3 _731 = mix(half4(_722).xxx, half4(_722).yyy, half3(float3(params.facet_f0)));
    float4 _700 = facet_environment.sample(facet_environmentSmplr, float3(_689), level(params.facet_environmentLod));
    half3 _554 = half4(frame.lightDirection).xyz;
    half _859 = clamp(dot(_689, _554), half(0.0), half(1.0));
    half _862 = _859 * _859;
    half4 _1472 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_862 * _862, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _874 = _1472.x;
    float3 _919 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _922 = dot(_919, _919);
    float3 _927 = _919 * rsqrt(fast::max(_922, 9.9999999392252902907785028219223e-09));
    float _931 = _922 * float(frame.punctualLights[0].positionFalloff.w);
    float _936 = fast::clamp(fma(-_931, _931, 1.0), 0.0, 1.0);
    float _955 = fast::clamp(fma(dot(-_927, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1087 = clamp(dot(_689, half3(_927)), half(0.0), half(1.0));
    half _1090 = _1087 * _1087;
    half4 _1497 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1090 * _1090, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1102 = _1497.x;
    float3 _1147 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1150 = dot(_1147, _1147);
    float3 _1155 = _1147 * rsqrt(fast::max(_1150, 9.9999999392252902907785028219223e-09));
    float _1159 = _1150 * float(frame.punctualLights[1].positionFalloff.w);
    float _1164 = fast::clamp(fma(-_1159, _1159, 1.0), 0.0, 1.0);
    float _1183 = fast::clamp(fma(dot(-_1155, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1315 = clamp(dot(_689, half3(_1155)), half(0.0), half(1.0));
    half _1318 = _1315 * _1315;
    half4 _1523 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1318 * _1318, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1330 = _1523.x;
    half3 _1339 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_700).xyz * _731) + min((_731 * ((_874 * _874) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_501, _554), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_731 * ((_1102 * _1102) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_936) * half(_936)) / fast::max(_922, 9.9999997473787516355514526367188e-05)) * half(_955)) * half(_955)), float3(65504.0))) * clamp(dot(_501, half3(_927)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_731 * ((_1330 * _1330) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1164) * half(_1164)) / fast::max(_1150, 9.9999997473787516355514526367188e-05)) * half(_1183)) * half(_1183)), float3(65504.0))) * clamp(dot(_501, half3(_1155)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1339, half(1.0)));
    return out;
}

