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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _562 = normalize(half3(in.v_normal));
    float3 _578 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _752 = max(dot(_562, half3(_578)), half(9.9999997473787516355514526367188e-05));
    float4 _791 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_752, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _810 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_791).y) - half(1.0)));
    float4 _822 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_578), _562)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _615 = half4(frame.lightDirection).xyz;
    half3 _929 = normalize(half3(_578) + _615);
    half _880 = clamp(dot(_562, _615), half(0.0), half(1.0));
    half3 _956 = cross(_562, _929);
    half _959 = clamp(dot(_562, _929), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _976 = max(mix((half(2.0) * _880) * _752, _880 + _752, half(params.facet_alpha)), half(0.000244140625));
    half _978 = half(1024.0) * half(params.facet_alpha);
    half _983 = _978 / (fma(_959, _959, dot(_956, _956)) * (half(6433.98193359375) * _976));
    float3 _1031 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1034 = dot(_1031, _1031);
    float3 _1039 = _1031 * rsqrt(fast::max(_1034, 9.9999999392252902907785028219223e-09));
    float _1043 = _1034 * float(frame.punctualLights[0].positionFalloff.w);
    float _1048 = fast::clamp(fma(-_1043, _1043, 1.0), 0.0, 1.0);
    float _1067 = fast::clamp(fma(dot(-_1039, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1177 = normalize(half3(_578) + half3(_1039));
    half _1128 = clamp(dot(_562, half3(_1039)), half(0.0), half(1.0));
    half3 _1204 = cross(_562, _1177);
    half _1207 = clamp(dot(_562, _1177), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1224 = max(mix((half(2.0) * _1128) * _752, _1128 + _752, half(params.facet_alpha)), half(0.000244140625));
    half _1231 = _978 / (fma(_1207, _1207, dot(_1204, _1204)) * (half(6433.98193359375) * _1224));
    float3 _1279 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1282 = dot(_1279, _1279);
    float3 _1287 = _1279 * rsqrt(fast::max(_1282, 9.9999999392252902907785028219223e-09));
    float _1291 = _1282 * float(frame.punctualLights[1].positionFalloff.w);
    float _1296 = fast::clamp(fma(-_1291, _1291, 1.0), 0.0, 1.0);
    float _1315 = fast::clamp(fma(dot(-_1287, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1425 = normalize(half3(_578) + half3(_1287));
    half _1376 = clamp(dot(_562, half3(_1287)), half(0.0), half(1.0));
    half3 _1452 = cross(_562, _1425);
    half _1455 = clamp(dot(_562, _1425), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1472 = max(mix((half(2.0) * _1376) * _752, _1376 + _752, half(params.facet_alpha)), half(0.000244140625));
    half _1479 = _978 / (fma(_1455, _1455, dot(_1452, _1452)) * (half(6433.98193359375) * _1472));
    half3 _1491 = (fma(half4(_822).xyz, mix(half4(_791).xxx, half4(_791).yyy, half3(float3(params.facet_f0))) * _810, min(((half3(float3(params.facet_f0)) * min(_983 * (_983 * (half(6.283185482025146484375) * _976)), half(65504.0))) * _810) * (half4(frame.lightColor).xyz * _880), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1231 * (_1231 * (half(6.283185482025146484375) * _1224)), half(65504.0))) * _810) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1048) * half(_1048)) / fast::max(_1034, 9.9999997473787516355514526367188e-05)) * half(_1067)) * half(_1067)), float3(65504.0))) * _1128), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1479 * (_1479 * (half(6.283185482025146484375) * _1472)), half(65504.0))) * _810) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1296) * half(_1296)) / fast::max(_1282, 9.9999997473787516355514526367188e-05)) * half(_1315)) * half(_1315)), float3(65504.0))) * _1376), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1491, half(1.0)));
    return out;
}

