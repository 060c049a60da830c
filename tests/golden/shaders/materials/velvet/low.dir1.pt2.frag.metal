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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _508 = normalize(half3(in.v_normal));
    float3 _524 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _691 = max(dot(_508, half3(_524)), half(9.9999997473787516355514526367188e-05));
    float4 _696 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_691, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _750 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1408 = half4(_696);
    half _709 = _1408.z;
    half4 _1412 = half4(_696);
    half _716 = _1412.w;
    float4 _771 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_524), _508)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _559 = half4(frame.lightDirection).xyz;
    half _793 = clamp(dot(_508, _559), half(0.0), half(1.0));
    half _805 = clamp(dot(_508, normalize(half3(_524) + _559)), half(0.0), half(1.0));
    half _850 = half(8192.0) * fma(half(-float(_793)), _691, _793 + _691);
    half _854 = half(1.0) / (half(params.facet_alpha) * _850);
    half _861 = half(2048.0) * half(params.facet_alpha);
    float3 _919 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _922 = dot(_919, _919);
    float3 _927 = _919 * rsqrt(fast::max(_922, 9.9999999392252902907785028219223e-09));
    float _931 = _922 * float(frame.punctualLights[0].positionFalloff.w);
    float _936 = fast::clamp(fma(-_931, _931, 1.0), 0.0, 1.0);
    float _955 = fast::clamp(fma(dot(-_927, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _988 = clamp(dot(_508, half3(_927)), half(0.0), half(1.0));
    half _1000 = clamp(dot(_508, normalize(half3(_524) + half3(_927))), half(0.0), half(1.0));
    half _1045 = half(8192.0) * fma(half(-float(_988)), _691, _988 + _691);
    half _1049 = half(1.0) / (half(params.facet_alpha) * _1045);
    float3 _1114 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1117 = dot(_1114, _1114);
    float3 _1122 = _1114 * rsqrt(fast::max(_1117, 9.9999999392252902907785028219223e-09));
    float _1126 = _1117 * float(frame.punctualLights[1].positionFalloff.w);
    float _1131 = fast::clamp(fma(-_1126, _1126, 1.0), 0.0, 1.0);
    float _1150 = fast::clamp(fma(dot(-_1122, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1183 = clamp(dot(_508, half3(_1122)), half(0.0), half(1.0));
    half _1195 = clamp(dot(_508, normalize(half3(_524) + half3(_1122))), half(0.0), half(1.0));
    half _1240 = half(8192.0) * fma(half(-float(_1183)), _691, _1183 + _691);
    half _1244 = half(1.0) / (half(params.facet_alpha) * _1240);
    half3 _1273 = ((fma(half4(_771).xyz, _750 * _709, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_750.x, max(_750.y, _750.z)))), _709, half(1.0))) + min((_750 * ((((fma(_854, _850, half(2.0)) * pow(max(fma(half(-float(_805)), _805, half(1.0)), half(0.0)), half(0.5) * (_854 * _850))) * half(0.15915493667125701904296875)) * (_793 * (_854 * _861))) * _716)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + min((_750 * ((((fma(_1049, _1045, half(2.0)) * pow(max(fma(half(-float(_1000)), _1000, half(1.0)), half(0.0)), half(0.5) * (_1049 * _1045))) * half(0.15915493667125701904296875)) * (_988 * (_1049 * _861))) * _716)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_936) * half(_936)) / fast::max(_922, 9.9999997473787516355514526367188e-05)) * half(_955)) * half(_955)), float3(65504.0))), half3(float3(65504.0)))) + min((_750 * ((((fma(_1244, _1240, half(2.0)) * pow(max(fma(half(-float(_1195)), _1195, half(1.0)), half(0.0)), half(0.5) * (_1244 * _1240))) * half(0.15915493667125701904296875)) * (_1183 * (_1244 * _861))) * _716)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1131) * half(_1131)) / fast::max(_1117, 9.9999997473787516355514526367188e-05)) * half(_1150)) * half(_1150)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1273, half(1.0)));
    return out;
}

