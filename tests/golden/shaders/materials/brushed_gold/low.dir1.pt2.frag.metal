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
    half3 _545 = normalize(half3(in.v_normal));
    float3 _561 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _742 = reflect(-half3(_561), _545);
    float4 _778 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_545, half3(_561)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _809 = facet_environment.sample(facet_environmentSmplr, float3(_742), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _757 = mix(half4(_778).xxx, half4(_778).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_778).y) - half(1.0))));
    half3 _598 = half4(frame.lightDirection).xyz;
    half _938 = clamp(dot(_742, _598), half(0.0), half(1.0));
    half _941 = _938 * _938;
    half4 _1573 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_941 * _941, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _953 = _1573.x;
    float3 _998 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1001 = dot(_998, _998);
    float3 _1006 = _998 * rsqrt(fast::max(_1001, 9.9999999392252902907785028219223e-09));
    float _1010 = _1001 * float(frame.punctualLights[0].positionFalloff.w);
    float _1015 = fast::clamp(fma(-_1010, _1010, 1.0), 0.0, 1.0);
    float _1034 = fast::clamp(fma(dot(-_1006, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1166 = clamp(dot(_742, half3(_1006)), half(0.0), half(1.0));
    half _1169 = _1166 * _1166;
    half4 _1598 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1169 * _1169, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1181 = _1598.x;
    float3 _1226 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1229 = dot(_1226, _1226);
    float3 _1234 = _1226 * rsqrt(fast::max(_1229, 9.9999999392252902907785028219223e-09));
    float _1238 = _1229 * float(frame.punctualLights[1].positionFalloff.w);
    float _1243 = fast::clamp(fma(-_1238, _1238, 1.0), 0.0, 1.0);
    float _1262 = fast::clamp(fma(dot(-_1234, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1394 = clamp(dot(_742, half3(_1234)), half(0.0), half(1.0));
    half _1397 = _1394 * _1394;
    half4 _1624 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1397 * _1397, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1409 = _1624.x;
    half3 _1418 = (fma(half4(_809).xyz, _757, min((_757 * ((_953 * _953) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_545, _598), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_757 * ((_1181 * _1181) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1015) * half(_1015)) / fast::max(_1001, 9.9999997473787516355514526367188e-05)) * half(_1034)) * half(_1034)), float3(65504.0))) * clamp(dot(_545, half3(_1006)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_757 * ((_1409 * _1409) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1243) * half(_1243)) / fast::max(_1229, 9.9999997473787516355514526367188e-05)) * half(_1262)) * half(_1262)), float3(65504.0))) * clamp(dot(_545, half3(_1234)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1418, half(1.0)));
    return out;
}

