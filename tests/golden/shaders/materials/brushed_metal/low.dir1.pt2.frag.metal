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
    half3 _824 = reflect(-half3(_597), _591);
    float4 _857 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_591, half3(_597)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    half3 _866 = mix(half4(_857).xxx, half4(_857).yyy, half3(float3(params.facet_f0)));
    float4 _835 = facet_environment.sample(facet_environmentSmplr, float3(_824), level(params.facet_environmentLod));
    half3 _631 = half4(frame.lightDirection).xyz;
    half _1002 = clamp(dot(_824, _631), half(0.0), half(1.0));
    half _1005 = _1002 * _1002;
    half4 _1695 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1005 * _1005, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1017 = _1695.x;
    float3 _1076 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1079 = dot(_1076, _1076);
    float3 _1084 = _1076 * rsqrt(fast::max(_1079, 9.9999999392252902907785028219223e-09));
    float _1088 = _1079 * float(frame.punctualLights[0].positionFalloff.w);
    float _1093 = fast::clamp(fma(-_1088, _1088, 1.0), 0.0, 1.0);
    float _1112 = fast::clamp(fma(dot(-_1084, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1252 = clamp(dot(_824, half3(_1084)), half(0.0), half(1.0));
    half _1255 = _1252 * _1252;
    half4 _1720 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1255 * _1255, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1267 = _1720.x;
    float3 _1326 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1329 = dot(_1326, _1326);
    float3 _1334 = _1326 * rsqrt(fast::max(_1329, 9.9999999392252902907785028219223e-09));
    float _1338 = _1329 * float(frame.punctualLights[1].positionFalloff.w);
    float _1343 = fast::clamp(fma(-_1338, _1338, 1.0), 0.0, 1.0);
    float _1362 = fast::clamp(fma(dot(-_1334, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1502 = clamp(dot(_824, half3(_1334)), half(0.0), half(1.0));
    half _1505 = _1502 * _1502;
    half4 _1746 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1505 * _1505, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1517 = _1746.x;
    half3 _1540 = (fma(half4(_835).xyz, _866, min((_866 * ((_1017 * _1017) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_591, _631), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_866 * ((_1267 * _1267) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1093) * half(_1093)) / fast::max(_1079, 9.9999997473787516355514526367188e-05)) * half(_1112)) * half(_1112)), float3(65504.0))) * clamp(dot(_591, half3(_1084)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_866 * ((_1517 * _1517) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1343) * half(_1343)) / fast::max(_1329, 9.9999997473787516355514526367188e-05)) * half(_1362)) * half(_1362)), float3(65504.0))) * clamp(dot(_591, half3(_1334)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1540, half(1.0)));
    return out;
}

