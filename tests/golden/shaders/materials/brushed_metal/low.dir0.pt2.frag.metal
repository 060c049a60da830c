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
    half3 _553 = normalize(half3(in.v_normal));
    float3 _569 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _734 = reflect(-half3(_569), _553);
    float4 _770 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_553, half3(_569)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _801 = facet_environment.sample(facet_environmentSmplr, float3(_734), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _749 = mix(half4(_770).xxx, half4(_770).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_770).y) - half(1.0))));
    float3 _846 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _849 = dot(_846, _846);
    float3 _854 = _846 * rsqrt(fast::max(_849, 9.9999999392252902907785028219223e-09));
    float _858 = _849 * float(frame.punctualLights[0].positionFalloff.w);
    float _863 = fast::clamp(fma(-_858, _858, 1.0), 0.0, 1.0);
    float _882 = fast::clamp(fma(dot(-_854, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1014 = clamp(dot(_734, half3(_854)), half(0.0), half(1.0));
    half _1017 = _1014 * _1014;
    half4 _1442 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1017 * _1017, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1029 = _1442.x;
    float3 _1074 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1077 = dot(_1074, _1074);
    float3 _1082 = _1074 * rsqrt(fast::max(_1077, 9.9999999392252902907785028219223e-09));
    float _1086 = _1077 * float(frame.punctualLights[1].positionFalloff.w);
    float _1091 = fast::clamp(fma(-_1086, _1086, 1.0), 0.0, 1.0);
    float _1110 = fast::clamp(fma(dot(-_1082, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1242 = clamp(dot(_734, half3(_1082)), half(0.0), half(1.0));
    half _1245 = _1242 * _1242;
    half4 _1468 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1245 * _1245, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1257 = _1468.x;
    half3 _1266 = fma(half4(_801).xyz, _749, min((_749 * ((_1029 * _1029) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_863) * half(_863)) / fast::max(_849, 9.9999997473787516355514526367188e-05)) * half(_882)) * half(_882)), float3(65504.0))) * clamp(dot(_553, half3(_854)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_749 * ((_1257 * _1257) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1091) * half(_1091)) / fast::max(_1077, 9.9999997473787516355514526367188e-05)) * half(_1110)) * half(_1110)), float3(65504.0))) * clamp(dot(_553, half3(_1082)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1266, half(1.0)));
    return out;
}

