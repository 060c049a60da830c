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
    half3 _539 = normalize(half3(in.v_normal));
    float3 _555 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _736 = reflect(-half3(_555), _539);
    float4 _772 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_539, half3(_555)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _798 = facet_environment.sample(facet_environmentSmplr, float3(_736), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _751 = mix(half4(_772).xxx, half4(_772).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_772).y) - half(1.0))));
    half3 _592 = half4(frame.lightDirection).xyz;
    half _927 = clamp(dot(_736, _592), half(0.0), half(1.0));
    half _930 = _927 * _927;
    half4 _1560 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_930 * _930, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _942 = _1560.x;
    float3 _987 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _990 = dot(_987, _987);
    float3 _995 = _987 * rsqrt(fast::max(_990, 9.9999999392252902907785028219223e-09));
    float _999 = _990 * float(frame.punctualLights[0].positionFalloff.w);
    float _1004 = fast::clamp(fma(-_999, _999, 1.0), 0.0, 1.0);
    float _1023 = fast::clamp(fma(dot(-_995, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1155 = clamp(dot(_736, half3(_995)), half(0.0), half(1.0));
    half _1158 = _1155 * _1155;
    half4 _1585 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1158 * _1158, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1170 = _1585.x;
    float3 _1215 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1218 = dot(_1215, _1215);
    float3 _1223 = _1215 * rsqrt(fast::max(_1218, 9.9999999392252902907785028219223e-09));
    float _1227 = _1218 * float(frame.punctualLights[1].positionFalloff.w);
    float _1232 = fast::clamp(fma(-_1227, _1227, 1.0), 0.0, 1.0);
    float _1251 = fast::clamp(fma(dot(-_1223, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1383 = clamp(dot(_736, half3(_1223)), half(0.0), half(1.0));
    half _1386 = _1383 * _1383;
    half4 _1611 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1386 * _1386, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1398 = _1611.x;
    half3 _1407 = (fma(half4(_798).xyz, _751, min((_751 * ((_942 * _942) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_539, _592), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_751 * ((_1170 * _1170) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1004) * half(_1004)) / fast::max(_990, 9.9999997473787516355514526367188e-05)) * half(_1023)) * half(_1023)), float3(65504.0))) * clamp(dot(_539, half3(_995)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_751 * ((_1398 * _1398) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1232) * half(_1232)) / fast::max(_1218, 9.9999997473787516355514526367188e-05)) * half(_1251)) * half(_1251)), float3(65504.0))) * clamp(dot(_539, half3(_1223)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1407, half(1.0)));
    return out;
}

