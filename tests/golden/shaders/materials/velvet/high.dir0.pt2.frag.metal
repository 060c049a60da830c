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
    half3 _676 = normalize(half3(in.v_normal));
    float3 _682 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _818 = _676.y;
    half _823 = _676.z;
    half _828 = _676.x;
    half3 _896 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _818)) + (half4(frame.sh[2]).xyz * _823)) + (half4(frame.sh[3]).xyz * _828)) + (((((half4(frame.sh[4]).xyz * (_828 * _818)) + (half4(frame.sh[5]).xyz * (_818 * _823))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _823, _823, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_828 * _823))) + (half4(frame.sh[8]).xyz * fma(_828, _828, half(-float(_818 * _818))))), half3(float3(0.0)));
    half _937 = max(dot(_676, half3(_682)), half(9.9999997473787516355514526367188e-05));
    float4 _942 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_937, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _996 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1653 = half4(_942);
    half _955 = _1653.z;
    half _957 = fma(half(-float(max(_996.x, max(_996.y, _996.z)))), _955, half(1.0));
    half4 _1657 = half4(_942);
    half _962 = _1657.w;
    float4 _1015 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_682), _676)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1052 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1055 = dot(_1052, _1052);
    float3 _1060 = _1052 * rsqrt(fast::max(_1055, 9.9999999392252902907785028219223e-09));
    float _1064 = _1055 * float(frame.punctualLights[0].positionFalloff.w);
    float _1069 = fast::clamp(fma(-_1064, _1064, 1.0), 0.0, 1.0);
    float _1088 = fast::clamp(fma(dot(-_1060, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1122 = dot(_676, half3(_1060));
    half _1124 = clamp(_1122, half(0.0), half(1.0));
    half _1136 = clamp(dot(_676, half3(fast::normalize(_682 + _1060))), half(0.0), half(1.0));
    half _1207 = half(8192.0) * fma(half(-float(_1124)), _937, _1124 + _937);
    half _1211 = half(1.0) / (half(params.facet_alpha) * _1207);
    half _1218 = half(2048.0) * half(params.facet_alpha);
    half3 _1169 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1122 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1124), half3(float3(0.0)), half3(float3(1.0)))) * _957) + (_996 * ((((fma(_1211, _1207, half(2.0)) * pow(max(fma(half(-float(_1136)), _1136, half(1.0)), half(0.0)), half(0.5) * (_1211 * _1207))) * half(0.15915493667125701904296875)) * (_1124 * (_1211 * _1218))) * _962))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1069) * half(_1069)) / fast::max(_1055, 9.9999997473787516355514526367188e-05)) * half(_1088)) * half(_1088)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1282 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1285 = dot(_1282, _1282);
    float3 _1290 = _1282 * rsqrt(fast::max(_1285, 9.9999999392252902907785028219223e-09));
    float _1294 = _1285 * float(frame.punctualLights[1].positionFalloff.w);
    float _1299 = fast::clamp(fma(-_1294, _1294, 1.0), 0.0, 1.0);
    float _1318 = fast::clamp(fma(dot(-_1290, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1352 = dot(_676, half3(_1290));
    half _1354 = clamp(_1352, half(0.0), half(1.0));
    half _1366 = clamp(dot(_676, half3(fast::normalize(_682 + _1290))), half(0.0), half(1.0));
    half _1437 = half(8192.0) * fma(half(-float(_1354)), _937, _1354 + _937);
    half _1441 = half(1.0) / (half(params.facet_alpha) * _1437);
    half3 _1399 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1352 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1354), half3(float3(0.0)), half3(float3(1.0)))) * _957) + (_996 * ((((fma(_1441, _1437, half(2.0)) * pow(max(fma(half(-float(_1366)), _1366, half(1.0)), half(0.0)), half(0.5) * (_1441 * _1437))) * half(0.15915493667125701904296875)) * (_1354 * (_1441 * _1218))) * _962))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1299) * half(_1299)) / fast::max(_1285, 9.9999997473787516355514526367188e-05)) * half(_1318)) * half(_1318)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_1015).xyz, _996 * _955, (half3(float3(params.facet_diffuseColor)) * _896) * _957) + _1169) + _1399, half(1.0)));
    return out;
}

