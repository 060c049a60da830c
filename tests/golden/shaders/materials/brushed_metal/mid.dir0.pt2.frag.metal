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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    half3 _591 = normalize(half3(in.v_normal));
    float3 _597 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _803 = reflect(-half3(_597), _591);
    float4 _836 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_591, half3(_597)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    half3 _845 = mix(half4(_836).xxx, half4(_836).yyy, half3(float3(params.facet_f0)));
    float4 _814 = facet_environment.sample(facet_environmentSmplr, float3(_803), level(params.facet_environmentLod));
    float3 _889 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _892 = dot(_889, _889);
    float3 _897 = _889 * rsqrt(fast::max(_892, 9.9999999392252902907785028219223e-09));
    float _901 = _892 * float(frame.punctualLights[0].positionFalloff.w);
    float _906 = fast::clamp(fma(-_901, _901, 1.0), 0.0, 1.0);
    float _925 = fast::clamp(fma(dot(-_897, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1065 = clamp(dot(_803, half3(_897)), half(0.0), half(1.0));
    half _1068 = _1065 * _1065;
    half4 _1515 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1068 * _1068, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1080 = _1515.x;
    float3 _1139 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1142 = dot(_1139, _1139);
    float3 _1147 = _1139 * rsqrt(fast::max(_1142, 9.9999999392252902907785028219223e-09));
    float _1151 = _1142 * float(frame.punctualLights[1].positionFalloff.w);
    float _1156 = fast::clamp(fma(-_1151, _1151, 1.0), 0.0, 1.0);
    float _1175 = fast::clamp(fma(dot(-_1147, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1315 = clamp(dot(_803, half3(_1147)), half(0.0), half(1.0));
    half _1318 = _1315 * _1315;
    half4 _1541 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1318 * _1318, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1330 = _1541.x;
    half3 _1353 = fma(half4(_814).xyz, _845, min((_845 * ((_1080 * _1080) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_906) * half(_906)) / fast::max(_892, 9.9999997473787516355514526367188e-05)) * half(_925)) * half(_925)), float3(65504.0))) * clamp(dot(_591, half3(_897)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_845 * ((_1330 * _1330) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1156) * half(_1156)) / fast::max(_1142, 9.9999997473787516355514526367188e-05)) * half(_1175)) * half(_1175)), float3(65504.0))) * clamp(dot(_591, half3(_1147)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1353, half(1.0)));
    return out;
}

