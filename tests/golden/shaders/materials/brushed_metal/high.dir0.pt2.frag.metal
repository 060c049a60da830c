#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float anisotropy;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
    packed_float3 facet_f0;
    float facet_alpha;
    float facet_anisotropy;
    float facet_anisotropicBend;
    float2 facet_anisotropicAlpha;
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
    float4 v_tangent [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _922 = normalize(half3(in.v_normal));
    float3 _928 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _1065 = half4(in.v_tangent).xyz;
    half3 _1072 = _1065 - (_922 * dot(_922, _1065));
    half _1074 = _922.z;
    half3 _2166;
    if (float(abs(_1074)) < 0.5)
    {
        _2166 = half3(-_922.y, _922.x, half(0.0));
    }
    else
    {
        _2166 = half3(half(0.0), -_1074, _922.y);
    }
    half3 _1101 = normalize(half3(select(float3(_2166), float3(_1072), bool3(float(dot(_1072, _1072)) > 0.001000000047497451305389404296875))));
    half _948 = max(dot(_922, half3(_928)), half(9.9999997473787516355514526367188e-05));
    half3 _1114 = cross(_922, _1101);
    half2 _1120 = half2(float2(1.0)) / half2(params.facet_anisotropicAlpha);
    half2 _1122 = half2(params.facet_anisotropicAlpha) * half(128.0);
    half _1128 = half(0.3183098733425140380859375) * (_1120.x * _1120.y);
    half _1144 = length(half3(_1122 * half2(dot(_1101, half3(_928)), dot(_1114, half3(_928))), half(128.0) * _948));
    half3 _2182 = select(_1114, _1101, bool3(params.facet_anisotropy >= 0.0));
    half _1377 = dot(_2182, half3(_928));
    half _1384 = fma(half(-params.facet_anisotropicBend), half(1.0) - _948, half(1.0));
    half _1387 = half(params.facet_anisotropicBend) * _1377;
    float4 _1426 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_948, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1455 = facet_environment.sample(facet_environmentSmplr, float3(((((_922 * _1384) + (_2182 * _1387)) * (half(512.0) * fma(_1384, _948, _1387 * _1377))) - (half3(_928) * (half(256.0) * fma(_1384, _1384, _1387 * _1387))))), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1500 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1503 = dot(_1500, _1500);
    float3 _1508 = _1500 * rsqrt(fast::max(_1503, 9.9999999392252902907785028219223e-09));
    float _1512 = _1503 * float(frame.punctualLights[0].positionFalloff.w);
    float _1517 = fast::clamp(fma(-_1512, _1512, 1.0), 0.0, 1.0);
    float _1536 = fast::clamp(fma(dot(-_1508, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1646 = fast::normalize(_928 + _1508);
    half _1595 = clamp(dot(_922, half3(_1508)), half(0.0), half(1.0));
    half _1599 = clamp(dot(_922, half3(_1646)), half(0.0), half(1.0));
    half2 _1664 = half2(dot(_1101, half3(_1646)), dot(_1114, half3(_1646))) * _1120;
    half _1672 = half(1.0) / fma(_1599, _1599, dot(_1664, _1664));
    half _1713 = half(1.0) - clamp(dot(half3(_1508), half3(_1646)), half(0.0), half(1.0));
    half _1716 = _1713 * _1713;
    half3 _1724 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1627 = min(((half3(float3(params.facet_f0)) + (_1724 * ((_1716 * _1716) * _1713))) * min(((_1128 * _1672) * _1672) * min(half(64.0) / fma(_1595, _1144, _948 * length(half3(_1122 * half2(dot(_1101, half3(_1508)), dot(_1114, half3(_1508))), half(128.0) * _1595))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1517) * half(_1517)) / fast::max(_1503, 9.9999997473787516355514526367188e-05)) * half(_1536)) * half(_1536)), float3(65504.0))) * _1595), half3(float3(65504.0)));
    float3 _1782 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1785 = dot(_1782, _1782);
    float3 _1790 = _1782 * rsqrt(fast::max(_1785, 9.9999999392252902907785028219223e-09));
    float _1794 = _1785 * float(frame.punctualLights[1].positionFalloff.w);
    float _1799 = fast::clamp(fma(-_1794, _1794, 1.0), 0.0, 1.0);
    float _1818 = fast::clamp(fma(dot(-_1790, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1928 = fast::normalize(_928 + _1790);
    half _1877 = clamp(dot(_922, half3(_1790)), half(0.0), half(1.0));
    half _1881 = clamp(dot(_922, half3(_1928)), half(0.0), half(1.0));
    half2 _1946 = half2(dot(_1101, half3(_1928)), dot(_1114, half3(_1928))) * _1120;
    half _1954 = half(1.0) / fma(_1881, _1881, dot(_1946, _1946));
    half _1995 = half(1.0) - clamp(dot(half3(_1790), half3(_1928)), half(0.0), half(1.0));
    half _1998 = _1995 * _1995;
    half3 _1909 = min(((half3(float3(params.facet_f0)) + (_1724 * ((_1998 * _1998) * _1995))) * min(((_1128 * _1954) * _1954) * min(half(64.0) / fma(_1877, _1144, _948 * length(half3(_1122 * half2(dot(_1101, half3(_1790)), dot(_1114, half3(_1790))), half(128.0) * _1877))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1799) * half(_1799)) / fast::max(_1785, 9.9999997473787516355514526367188e-05)) * half(_1818)) * half(_1818)), float3(65504.0))) * _1877), half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_1455).xyz, mix(half4(_1426).xxx, half4(_1426).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1426).y) - half(1.0)))), _1627) + _1909, half(1.0)));
    return out;
}

