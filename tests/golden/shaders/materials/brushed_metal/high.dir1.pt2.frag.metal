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
    half3 _1086 = half4(in.v_tangent).xyz;
    half3 _1093 = _1086 - (_922 * dot(_922, _1086));
    half _1095 = _922.z;
    half3 _2389;
    if (float(abs(_1095)) < 0.5)
    {
        _2389 = half3(-_922.y, _922.x, half(0.0));
    }
    else
    {
        _2389 = half3(half(0.0), -_1095, _922.y);
    }
    half3 _1122 = normalize(half3(select(float3(_2389), float3(_1093), bool3(float(dot(_1093, _1093)) > 0.001000000047497451305389404296875))));
    half _948 = max(dot(_922, half3(_928)), half(9.9999997473787516355514526367188e-05));
    half3 _1135 = cross(_922, _1122);
    half2 _1141 = half2(float2(1.0)) / half2(params.facet_anisotropicAlpha);
    half2 _1143 = half2(params.facet_anisotropicAlpha) * half(128.0);
    half _1149 = half(0.3183098733425140380859375) * (_1141.x * _1141.y);
    half _1165 = length(half3(_1143 * half2(dot(_1122, half3(_928)), dot(_1135, half3(_928))), half(128.0) * _948));
    half3 _2405 = select(_1135, _1122, bool3(params.facet_anisotropy >= 0.0));
    half _1398 = dot(_2405, half3(_928));
    half _1405 = fma(half(-params.facet_anisotropicBend), half(1.0) - _948, half(1.0));
    half _1408 = half(params.facet_anisotropicBend) * _1398;
    float4 _1447 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_948, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1476 = facet_environment.sample(facet_environmentSmplr, float3(((((_922 * _1405) + (_2405 * _1408)) * (half(512.0) * fma(_1405, _948, _1408 * _1398))) - (half3(_928) * (half(256.0) * fma(_1405, _1405, _1408 * _1408))))), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1583 = fast::normalize(_928 + frame.lightDirection.xyz);
    half _1532 = clamp(dot(_922, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1536 = clamp(dot(_922, half3(_1583)), half(0.0), half(1.0));
    half2 _1601 = half2(dot(_1122, half3(_1583)), dot(_1135, half3(_1583))) * _1141;
    half _1609 = half(1.0) / fma(_1536, _1536, dot(_1601, _1601));
    half _1650 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1583)), half(0.0), half(1.0));
    half _1653 = _1650 * _1650;
    half3 _1661 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1719 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1722 = dot(_1719, _1719);
    float3 _1727 = _1719 * rsqrt(fast::max(_1722, 9.9999999392252902907785028219223e-09));
    float _1731 = _1722 * float(frame.punctualLights[0].positionFalloff.w);
    float _1736 = fast::clamp(fma(-_1731, _1731, 1.0), 0.0, 1.0);
    float _1755 = fast::clamp(fma(dot(-_1727, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1865 = fast::normalize(_928 + _1727);
    half _1814 = clamp(dot(_922, half3(_1727)), half(0.0), half(1.0));
    half _1818 = clamp(dot(_922, half3(_1865)), half(0.0), half(1.0));
    half2 _1883 = half2(dot(_1122, half3(_1865)), dot(_1135, half3(_1865))) * _1141;
    half _1891 = half(1.0) / fma(_1818, _1818, dot(_1883, _1883));
    half _1932 = half(1.0) - clamp(dot(half3(_1727), half3(_1865)), half(0.0), half(1.0));
    half _1935 = _1932 * _1932;
    half3 _1846 = min(((half3(float3(params.facet_f0)) + (_1661 * ((_1935 * _1935) * _1932))) * min(((_1149 * _1891) * _1891) * min(half(64.0) / fma(_1814, _1165, _948 * length(half3(_1143 * half2(dot(_1122, half3(_1727)), dot(_1135, half3(_1727))), half(128.0) * _1814))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1736) * half(_1736)) / fast::max(_1722, 9.9999997473787516355514526367188e-05)) * half(_1755)) * half(_1755)), float3(65504.0))) * _1814), half3(float3(65504.0)));
    half3 _1965 = fma(half4(_1476).xyz, mix(half4(_1447).xxx, half4(_1447).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1447).y) - half(1.0)))), min(((half3(float3(params.facet_f0)) + (_1661 * ((_1653 * _1653) * _1650))) * min(((_1149 * _1609) * _1609) * min(half(64.0) / fma(_1532, _1165, _948 * length(half3(_1143 * half2(dot(_1122, half3(frame.lightDirection.xyz)), dot(_1135, half3(frame.lightDirection.xyz))), half(128.0) * _1532))), half(65504.0)), half(65504.0))) * (half4(frame.lightColor).xyz * _1532), half3(float3(65504.0)))) + _1846;
    float3 _2001 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2004 = dot(_2001, _2001);
    float3 _2009 = _2001 * rsqrt(fast::max(_2004, 9.9999999392252902907785028219223e-09));
    float _2013 = _2004 * float(frame.punctualLights[1].positionFalloff.w);
    float _2018 = fast::clamp(fma(-_2013, _2013, 1.0), 0.0, 1.0);
    float _2037 = fast::clamp(fma(dot(-_2009, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2147 = fast::normalize(_928 + _2009);
    half _2096 = clamp(dot(_922, half3(_2009)), half(0.0), half(1.0));
    half _2100 = clamp(dot(_922, half3(_2147)), half(0.0), half(1.0));
    half2 _2165 = half2(dot(_1122, half3(_2147)), dot(_1135, half3(_2147))) * _1141;
    half _2173 = half(1.0) / fma(_2100, _2100, dot(_2165, _2165));
    half _2214 = half(1.0) - clamp(dot(half3(_2009), half3(_2147)), half(0.0), half(1.0));
    half _2217 = _2214 * _2214;
    half3 _2128 = min(((half3(float3(params.facet_f0)) + (_1661 * ((_2217 * _2217) * _2214))) * min(((_1149 * _2173) * _2173) * min(half(64.0) / fma(_2096, _1165, _948 * length(half3(_1143 * half2(dot(_1122, half3(_2009)), dot(_1135, half3(_2009))), half(128.0) * _2096))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2018) * half(_2018)) / fast::max(_2004, 9.9999997473787516355514526367188e-05)) * half(_2037)) * half(_2037)), float3(65504.0))) * _2096), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1965 + _2128, half(1.0)));
    return out;
}

