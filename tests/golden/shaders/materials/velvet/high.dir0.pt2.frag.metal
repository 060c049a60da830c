#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    half3 _642 = normalize(half3(in.v_normal));
    float3 _648 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _784 = _642.y;
    half _789 = _642.z;
    half _794 = _642.x;
    half3 _862 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _784)) + (half4(frame.sh[2]).xyz * _789)) + (half4(frame.sh[3]).xyz * _794)) + (((((half4(frame.sh[4]).xyz * (_794 * _784)) + (half4(frame.sh[5]).xyz * (_784 * _789))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _789, _789, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_794 * _789))) + (half4(frame.sh[8]).xyz * fma(_794, _794, half(-float(_784 * _784))))), half3(float3(0.0)));
    half _902 = max(dot(_642, half3(_648)), half(9.9999997473787516355514526367188e-05));
    float4 _907 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_902, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _953 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1618 = half4(_907);
    half _920 = _1618.z;
    half _922 = fma(half(-float(max(_953.x, max(_953.y, _953.z)))), _920, half(1.0));
    half4 _1622 = half4(_907);
    half _924 = _1622.w;
    float4 _960 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_648), _642)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _997 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1000 = dot(_997, _997);
    float3 _1005 = _997 * rsqrt(fast::max(_1000, 9.9999999392252902907785028219223e-09));
    float _1009 = _1000 * float(frame.punctualLights[0].positionFalloff.w);
    float _1014 = fast::clamp(fma(-_1009, _1009, 1.0), 0.0, 1.0);
    float _1033 = fast::clamp(fma(dot(-_1005, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1071 = dot(_642, half3(_1005));
    half _1073 = clamp(_1071, half(0.0), half(1.0));
    half _1087 = clamp(dot(_642, half3(fast::normalize(_648 + _1005))), half(0.0), half(1.0));
    half _1160 = half(8192.0) * fma(half(-float(_1073)), _902, _1073 + _902);
    half _1164 = half(1.0) / (half(params.facet_alpha) * _1160);
    half _1171 = half(2048.0) * half(params.facet_alpha);
    half3 _1126 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1071 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1073), half3(float3(0.0)), half3(float3(1.0)))) * _922) + (_953 * ((((fma(_1164, _1160, half(2.0)) * pow(max(fma(half(-float(_1087)), _1087, half(1.0)), half(0.0)), half(0.5) * (_1164 * _1160))) * half(0.15915493667125701904296875)) * (_1073 * (_1164 * _1171))) * _924))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1014) * half(_1014)) / fast::max(_1000, 9.9999997473787516355514526367188e-05)) * half(_1033)) * half(_1033)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1235 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1238 = dot(_1235, _1235);
    float3 _1243 = _1235 * rsqrt(fast::max(_1238, 9.9999999392252902907785028219223e-09));
    float _1247 = _1238 * float(frame.punctualLights[1].positionFalloff.w);
    float _1252 = fast::clamp(fma(-_1247, _1247, 1.0), 0.0, 1.0);
    float _1271 = fast::clamp(fma(dot(-_1243, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1309 = dot(_642, half3(_1243));
    half _1311 = clamp(_1309, half(0.0), half(1.0));
    half _1325 = clamp(dot(_642, half3(fast::normalize(_648 + _1243))), half(0.0), half(1.0));
    half _1398 = half(8192.0) * fma(half(-float(_1311)), _902, _1311 + _902);
    half _1402 = half(1.0) / (half(params.facet_alpha) * _1398);
    half3 _1364 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1309 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1311), half3(float3(0.0)), half3(float3(1.0)))) * _922) + (_953 * ((((fma(_1402, _1398, half(2.0)) * pow(max(fma(half(-float(_1325)), _1325, half(1.0)), half(0.0)), half(0.5) * (_1402 * _1398))) * half(0.15915493667125701904296875)) * (_1311 * (_1402 * _1171))) * _924))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1252) * half(_1252)) / fast::max(_1238, 9.9999997473787516355514526367188e-05)) * half(_1271)) * half(_1271)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_960).xyz, _953 * _920, (half3(float3(params.facet_diffuseColor)) * _862) * _922) + _1126) + _1364, half(1.0)));
    return out;
}

