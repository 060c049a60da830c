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
    half3 _502 = normalize(half3(in.v_normal));
    float3 _518 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _683 = max(dot(_502, half3(_518)), half(9.9999997473787516355514526367188e-05));
    float4 _688 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_683, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _742 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1395 = half4(_688);
    half _701 = _1395.z;
    half4 _1399 = half4(_688);
    half _708 = _1399.w;
    float4 _758 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_518), _502)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _553 = half4(frame.lightDirection).xyz;
    half _780 = clamp(dot(_502, _553), half(0.0), half(1.0));
    half _792 = clamp(dot(_502, normalize(half3(_518) + _553)), half(0.0), half(1.0));
    half _837 = half(8192.0) * fma(half(-float(_780)), _683, _780 + _683);
    half _841 = half(1.0) / (half(params.facet_alpha) * _837);
    half _848 = half(2048.0) * half(params.facet_alpha);
    float3 _906 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _909 = dot(_906, _906);
    float3 _914 = _906 * rsqrt(fast::max(_909, 9.9999999392252902907785028219223e-09));
    float _918 = _909 * float(frame.punctualLights[0].positionFalloff.w);
    float _923 = fast::clamp(fma(-_918, _918, 1.0), 0.0, 1.0);
    float _942 = fast::clamp(fma(dot(-_914, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _975 = clamp(dot(_502, half3(_914)), half(0.0), half(1.0));
    half _987 = clamp(dot(_502, normalize(half3(_518) + half3(_914))), half(0.0), half(1.0));
    half _1032 = half(8192.0) * fma(half(-float(_975)), _683, _975 + _683);
    half _1036 = half(1.0) / (half(params.facet_alpha) * _1032);
    float3 _1101 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1104 = dot(_1101, _1101);
    float3 _1109 = _1101 * rsqrt(fast::max(_1104, 9.9999999392252902907785028219223e-09));
    float _1113 = _1104 * float(frame.punctualLights[1].positionFalloff.w);
    float _1118 = fast::clamp(fma(-_1113, _1113, 1.0), 0.0, 1.0);
    float _1137 = fast::clamp(fma(dot(-_1109, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1170 = clamp(dot(_502, half3(_1109)), half(0.0), half(1.0));
    half _1182 = clamp(dot(_502, normalize(half3(_518) + half3(_1109))), half(0.0), half(1.0));
    half _1227 = half(8192.0) * fma(half(-float(_1170)), _683, _1170 + _683);
    half _1231 = half(1.0) / (half(params.facet_alpha) * _1227);
    half3 _1260 = ((fma(half4(_758).xyz, _742 * _701, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_742.x, max(_742.y, _742.z)))), _701, half(1.0))) + min((_742 * ((((fma(_841, _837, half(2.0)) * pow(max(fma(half(-float(_792)), _792, half(1.0)), half(0.0)), half(0.5) * (_841 * _837))) * half(0.15915493667125701904296875)) * (_780 * (_841 * _848))) * _708)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + min((_742 * ((((fma(_1036, _1032, half(2.0)) * pow(max(fma(half(-float(_987)), _987, half(1.0)), half(0.0)), half(0.5) * (_1036 * _1032))) * half(0.15915493667125701904296875)) * (_975 * (_1036 * _848))) * _708)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_923) * half(_923)) / fast::max(_909, 9.9999997473787516355514526367188e-05)) * half(_942)) * half(_942)), float3(65504.0))), half3(float3(65504.0)))) + min((_742 * ((((fma(_1231, _1227, half(2.0)) * pow(max(fma(half(-float(_1182)), _1182, half(1.0)), half(0.0)), half(0.5) * (_1231 * _1227))) * half(0.15915493667125701904296875)) * (_1170 * (_1231 * _848))) * _708)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1118) * half(_1118)) / fast::max(_1104, 9.9999997473787516355514526367188e-05)) * half(_1137)) * half(_1137)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1260, half(1.0)));
    return out;
}

