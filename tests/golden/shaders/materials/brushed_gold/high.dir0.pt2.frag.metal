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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _771 = normalize(half3(in.v_normal));
    float3 _777 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1042 = max(dot(_771, half3(_777)), half(9.9999997473787516355514526367188e-05));
    float4 _1084 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1042, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1103 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1084).y) - half(1.0)));
    float4 _1060 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_777), _771)), level(params.facet_environmentLod));
    float3 _1147 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1150 = dot(_1147, _1147);
    float3 _1155 = _1147 * rsqrt(fast::max(_1150, 9.9999999392252902907785028219223e-09));
    float _1159 = _1150 * float(frame.punctualLights[0].positionFalloff.w);
    float _1164 = fast::clamp(fma(-_1159, _1159, 1.0), 0.0, 1.0);
    float _1183 = fast::clamp(fma(dot(-_1155, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1243 = clamp(dot(_771, half3(_1155)), half(0.0), half(1.0));
    float3 _1302 = fast::normalize(_777 + _1155);
    half _1342 = half(4096.0) * half(params.facet_alpha);
    half4 _1367 = half4(cross(_771, half3(_1302)), half(params.facet_alpha) * clamp(dot(_771, half3(_1302)), half(0.0), half(1.0))) * half(64.0);
    half _1348 = _1342 / dot(_1367, _1367);
    half _1378 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1384 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1388 = sqrt(fma(_1042 * _1042, _1384, _1378));
    half _1412 = half(1.0) - clamp(dot(half3(_1155), half3(_1302)), half(0.0), half(1.0));
    half _1415 = _1412 * _1412;
    half3 _1423 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1481 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1484 = dot(_1481, _1481);
    float3 _1489 = _1481 * rsqrt(fast::max(_1484, 9.9999999392252902907785028219223e-09));
    float _1493 = _1484 * float(frame.punctualLights[1].positionFalloff.w);
    float _1498 = fast::clamp(fma(-_1493, _1493, 1.0), 0.0, 1.0);
    float _1517 = fast::clamp(fma(dot(-_1489, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1577 = clamp(dot(_771, half3(_1489)), half(0.0), half(1.0));
    float3 _1636 = fast::normalize(_777 + _1489);
    half4 _1701 = half4(cross(_771, half3(_1636)), half(params.facet_alpha) * clamp(dot(_771, half3(_1636)), half(0.0), half(1.0))) * half(64.0);
    half _1682 = _1342 / dot(_1701, _1701);
    half _1746 = half(1.0) - clamp(dot(half3(_1489), half3(_1636)), half(0.0), half(1.0));
    half _1749 = _1746 * _1746;
    half3 _1779 = fma(half4(_1060).xyz, mix(half4(_1084).xxx, half4(_1084).yyy, half3(float3(params.facet_f0))) * _1103, min((((half3(float3(params.facet_f0)) + (_1423 * ((_1415 * _1415) * _1412))) * min(min((_1348 * _1348) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1243, _1388, _1042 * sqrt(fma(_1243 * _1243, _1384, _1378))), half(65504.0)), half(65504.0))) * _1103) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1164) * half(_1164)) / fast::max(_1150, 9.9999997473787516355514526367188e-05)) * half(_1183)) * half(_1183)), float3(65504.0))) * _1243), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1423 * ((_1749 * _1749) * _1746))) * min(min((_1682 * _1682) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1577, _1388, _1042 * sqrt(fma(_1577 * _1577, _1384, _1378))), half(65504.0)), half(65504.0))) * _1103) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1498) * half(_1498)) / fast::max(_1484, 9.9999997473787516355514526367188e-05)) * half(_1517)) * half(_1517)), float3(65504.0))) * _1577), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1779, half(1.0)));
    return out;
}

