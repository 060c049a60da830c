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
    half3 _542 = normalize(half3(in.v_normal));
    float3 _558 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _713 = reflect(-half3(_558), _542);
    float4 _749 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_542, half3(_558)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _780 = facet_environment.sample(facet_environmentSmplr, float3(_713), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _728 = mix(half4(_749).xxx, half4(_749).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_749).y) - half(1.0))));
    float3 _825 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _828 = dot(_825, _825);
    float3 _833 = _825 * rsqrt(fast::max(_828, 9.9999999392252902907785028219223e-09));
    float _837 = _828 * float(frame.punctualLights[0].positionFalloff.w);
    float _842 = fast::clamp(fma(-_837, _837, 1.0), 0.0, 1.0);
    float _861 = fast::clamp(fma(dot(-_833, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _993 = clamp(dot(_713, half3(_833)), half(0.0), half(1.0));
    half _996 = _993 * _993;
    half4 _1399 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_996 * _996, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1008 = _1399.x;
    float3 _1053 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1056 = dot(_1053, _1053);
    float3 _1061 = _1053 * rsqrt(fast::max(_1056, 9.9999999392252902907785028219223e-09));
    float _1065 = _1056 * float(frame.punctualLights[1].positionFalloff.w);
    float _1070 = fast::clamp(fma(-_1065, _1065, 1.0), 0.0, 1.0);
    float _1089 = fast::clamp(fma(dot(-_1061, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1221 = clamp(dot(_713, half3(_1061)), half(0.0), half(1.0));
    half _1224 = _1221 * _1221;
    half4 _1425 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1224 * _1224, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1236 = _1425.x;
    half3 _1245 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_780).xyz * _728) + min((_728 * ((_1008 * _1008) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_842) * half(_842)) / fast::max(_828, 9.9999997473787516355514526367188e-05)) * half(_861)) * half(_861)), float3(65504.0))) * clamp(dot(_542, half3(_833)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_728 * ((_1236 * _1236) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1070) * half(_1070)) / fast::max(_1056, 9.9999997473787516355514526367188e-05)) * half(_1089)) * half(_1089)), float3(65504.0))) * clamp(dot(_542, half3(_1061)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1245, half(1.0)));
    return out;
}

