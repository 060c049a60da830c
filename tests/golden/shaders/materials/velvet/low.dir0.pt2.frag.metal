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
    half _670 = max(dot(_508, half3(_524)), half(9.9999997473787516355514526367188e-05));
    float4 _675 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_670, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _729 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1274 = half4(_675);
    half _688 = _1274.z;
    half4 _1278 = half4(_675);
    half _695 = _1278.w;
    float4 _750 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_524), _508)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _787 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _790 = dot(_787, _787);
    float3 _795 = _787 * rsqrt(fast::max(_790, 9.9999999392252902907785028219223e-09));
    float _799 = _790 * float(frame.punctualLights[0].positionFalloff.w);
    float _804 = fast::clamp(fma(-_799, _799, 1.0), 0.0, 1.0);
    float _823 = fast::clamp(fma(dot(-_795, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _856 = clamp(dot(_508, half3(_795)), half(0.0), half(1.0));
    half _868 = clamp(dot(_508, normalize(half3(_524) + half3(_795))), half(0.0), half(1.0));
    half _913 = half(8192.0) * fma(half(-float(_856)), _670, _856 + _670);
    half _917 = half(1.0) / (half(params.facet_alpha) * _913);
    half _924 = half(2048.0) * half(params.facet_alpha);
    float3 _982 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _985 = dot(_982, _982);
    float3 _990 = _982 * rsqrt(fast::max(_985, 9.9999999392252902907785028219223e-09));
    float _994 = _985 * float(frame.punctualLights[1].positionFalloff.w);
    float _999 = fast::clamp(fma(-_994, _994, 1.0), 0.0, 1.0);
    float _1018 = fast::clamp(fma(dot(-_990, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1051 = clamp(dot(_508, half3(_990)), half(0.0), half(1.0));
    half _1063 = clamp(dot(_508, normalize(half3(_524) + half3(_990))), half(0.0), half(1.0));
    half _1108 = half(8192.0) * fma(half(-float(_1051)), _670, _1051 + _670);
    half _1112 = half(1.0) / (half(params.facet_alpha) * _1108);
    half3 _1141 = (fma(half4(_750).xyz, _729 * _688, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_729.x, max(_729.y, _729.z)))), _688, half(1.0))) + min((_729 * ((((fma(_917, _913, half(2.0)) * pow(max(fma(half(-float(_868)), _868, half(1.0)), half(0.0)), half(0.5) * (_917 * _913))) * half(0.15915493667125701904296875)) * (_856 * (_917 * _924))) * _695)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_804) * half(_804)) / fast::max(_790, 9.9999997473787516355514526367188e-05)) * half(_823)) * half(_823)), float3(65504.0))), half3(float3(65504.0)))) + min((_729 * ((((fma(_1112, _1108, half(2.0)) * pow(max(fma(half(-float(_1063)), _1063, half(1.0)), half(0.0)), half(0.5) * (_1112 * _1108))) * half(0.15915493667125701904296875)) * (_1051 * (_1112 * _924))) * _695)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_999) * half(_999)) / fast::max(_985, 9.9999997473787516355514526367188e-05)) * half(_1018)) * half(_1018)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1141, half(1.0)));
    return out;
}

