#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
    packed_float3 facet_f0;
    float facet_alpha;
    float facet_clearCoat;
    float facet_clearCoatAlpha;
    float facet_clearCoatLod;
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
    half3 _625 = normalize(half3(in.v_normal));
    float3 _641 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _835 = max(dot(_625, half3(_641)), half(9.9999997473787516355514526367188e-05));
    half3 _839 = reflect(-half3(_641), _625);
    float4 _875 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_835, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _904 = facet_environment.sample(facet_environmentSmplr, float3(_839), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _854 = mix(half4(_875).xxx, half4(_875).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_875).y) - half(1.0))));
    half3 _679 = half4(frame.lightDirection).xyz;
    half _1033 = clamp(dot(_839, _679), half(0.0), half(1.0));
    half _1036 = _1033 * _1033;
    half4 _1735 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1036 * _1036, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1048 = _1735.x;
    float3 _1093 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1096 = dot(_1093, _1093);
    float3 _1101 = _1093 * rsqrt(fast::max(_1096, 9.9999999392252902907785028219223e-09));
    float _1105 = _1096 * float(frame.punctualLights[0].positionFalloff.w);
    float _1110 = fast::clamp(fma(-_1105, _1105, 1.0), 0.0, 1.0);
    float _1129 = fast::clamp(fma(dot(-_1101, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1261 = clamp(dot(_839, half3(_1101)), half(0.0), half(1.0));
    half _1264 = _1261 * _1261;
    half4 _1760 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1264 * _1264, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1276 = _1760.x;
    float3 _1321 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1324 = dot(_1321, _1321);
    float3 _1329 = _1321 * rsqrt(fast::max(_1324, 9.9999999392252902907785028219223e-09));
    float _1333 = _1324 * float(frame.punctualLights[1].positionFalloff.w);
    float _1338 = fast::clamp(fma(-_1333, _1333, 1.0), 0.0, 1.0);
    float _1357 = fast::clamp(fma(dot(-_1329, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1489 = clamp(dot(_839, half3(_1329)), half(0.0), half(1.0));
    half _1492 = _1489 * _1489;
    half4 _1786 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1492 * _1492, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1504 = _1786.x;
    half3 _1513 = (fma(half4(_904).xyz, _854, min((_854 * ((_1048 * _1048) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_625, _679), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_854 * ((_1276 * _1276) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1110) * half(_1110)) / fast::max(_1096, 9.9999997473787516355514526367188e-05)) * half(_1129)) * half(_1129)), float3(65504.0))) * clamp(dot(_625, half3(_1101)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_854 * ((_1504 * _1504) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1338) * half(_1338)) / fast::max(_1324, 9.9999997473787516355514526367188e-05)) * half(_1357)) * half(_1357)), float3(65504.0))) * clamp(dot(_625, half3(_1329)), half(0.0), half(1.0))), half3(float3(65504.0)));
    half _1551 = half(1.0) - _835;
    half _1554 = _1551 * _1551;
    float4 _1539 = facet_environment.sample(facet_environmentSmplr, float3(_839), level(params.facet_clearCoatLod));
    out.fragColor = float4(half4(mix(_1513, half4(_1539).xyz, half3(fma(half(0.959999978542327880859375), (_1554 * _1554) * _1551, half(0.039999999105930328369140625)) * half(params.facet_clearCoat))), half(1.0)));
    return out;
}

