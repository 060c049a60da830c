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
    half3 _941 = normalize(half3(in.v_normal));
    float3 _947 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _1103 = half4(in.v_tangent).xyz;
    half3 _1110 = _1103 - (_941 * dot(_941, _1103));
    half _1112 = _941.z;
    half3 _2433;
    if (float(abs(_1112)) < 0.5)
    {
        _2433 = half3(-_941.y, _941.x, half(0.0));
    }
    else
    {
        _2433 = half3(half(0.0), -_1112, _941.y);
    }
    half3 _1139 = normalize(half3(select(float3(_2433), float3(_1110), bool3(float(dot(_1110, _1110)) > 0.001000000047497451305389404296875))));
    half _967 = max(dot(_941, half3(_947)), half(9.9999997473787516355514526367188e-05));
    half3 _1152 = cross(_941, _1139);
    half _1203 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half2 _1198 = clamp(half2(half(1.0) + _1203, half(1.0) - _1203) * half(params.facet_alpha), half2(float2(0.007921000011265277862548828125)), half2(float2(1.0)));
    half2 _1158 = half2(float2(1.0)) / _1198;
    half2 _1160 = _1198 * half(128.0);
    half _1166 = half(0.3183098733425140380859375) * (_1158.x * _1158.y);
    half _1182 = length(half3(_1160 * half2(dot(_1139, half3(_947)), dot(_1152, half3(_947))), half(128.0) * _967));
    half3 _2449 = select(_1152, _1139, bool3(float(_1203) >= 0.0));
    half _1432 = dot(_2449, half3(_947));
    half _1439 = min(abs(_1203) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _1444 = fma(half(-float(_1439)), half(1.0) - _967, half(1.0));
    half _1447 = _1439 * _1432;
    float4 _1487 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_967, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1516 = facet_environment.sample(facet_environmentSmplr, float3(((((_941 * _1444) + (_2449 * _1447)) * (half(512.0) * fma(_1444, _967, _1447 * _1432))) - (half3(_947) * (half(256.0) * fma(_1444, _1444, _1447 * _1447))))), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1623 = fast::normalize(_947 + frame.lightDirection.xyz);
    half _1572 = clamp(dot(_941, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1576 = clamp(dot(_941, half3(_1623)), half(0.0), half(1.0));
    half2 _1641 = half2(dot(_1139, half3(_1623)), dot(_1152, half3(_1623))) * _1158;
    half _1649 = half(1.0) / fma(_1576, _1576, dot(_1641, _1641));
    half _1690 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1623)), half(0.0), half(1.0));
    half _1693 = _1690 * _1690;
    half3 _1701 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1759 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1762 = dot(_1759, _1759);
    float3 _1767 = _1759 * rsqrt(fast::max(_1762, 9.9999999392252902907785028219223e-09));
    float _1771 = _1762 * float(frame.punctualLights[0].positionFalloff.w);
    float _1776 = fast::clamp(fma(-_1771, _1771, 1.0), 0.0, 1.0);
    float _1795 = fast::clamp(fma(dot(-_1767, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1905 = fast::normalize(_947 + _1767);
    half _1854 = clamp(dot(_941, half3(_1767)), half(0.0), half(1.0));
    half _1858 = clamp(dot(_941, half3(_1905)), half(0.0), half(1.0));
    half2 _1923 = half2(dot(_1139, half3(_1905)), dot(_1152, half3(_1905))) * _1158;
    half _1931 = half(1.0) / fma(_1858, _1858, dot(_1923, _1923));
    half _1972 = half(1.0) - clamp(dot(half3(_1767), half3(_1905)), half(0.0), half(1.0));
    half _1975 = _1972 * _1972;
    half3 _1886 = min(((half3(float3(params.facet_f0)) + (_1701 * ((_1975 * _1975) * _1972))) * min(((_1166 * _1931) * _1931) * min(half(64.0) / fma(_1854, _1182, _967 * length(half3(_1160 * half2(dot(_1139, half3(_1767)), dot(_1152, half3(_1767))), half(128.0) * _1854))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1776) * half(_1776)) / fast::max(_1762, 9.9999997473787516355514526367188e-05)) * half(_1795)) * half(_1795)), float3(65504.0))) * _1854), half3(float3(65504.0)));
    half3 _2005 = fma(half4(_1516).xyz, mix(half4(_1487).xxx, half4(_1487).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1487).y) - half(1.0)))), min(((half3(float3(params.facet_f0)) + (_1701 * ((_1693 * _1693) * _1690))) * min(((_1166 * _1649) * _1649) * min(half(64.0) / fma(_1572, _1182, _967 * length(half3(_1160 * half2(dot(_1139, half3(frame.lightDirection.xyz)), dot(_1152, half3(frame.lightDirection.xyz))), half(128.0) * _1572))), half(65504.0)), half(65504.0))) * (half4(frame.lightColor).xyz * _1572), half3(float3(65504.0)))) + _1886;
    float3 _2041 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2044 = dot(_2041, _2041);
    float3 _2049 = _2041 * rsqrt(fast::max(_2044, 9.9999999392252902907785028219223e-09));
    float _2053 = _2044 * float(frame.punctualLights[1].positionFalloff.w);
    float _2058 = fast::clamp(fma(-_2053, _2053, 1.0), 0.0, 1.0);
    float _2077 = fast::clamp(fma(dot(-_2049, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2187 = fast::normalize(_947 + _2049);
    half _2136 = clamp(dot(_941, half3(_2049)), half(0.0), half(1.0));
    half _2140 = clamp(dot(_941, half3(_2187)), half(0.0), half(1.0));
    half2 _2205 = half2(dot(_1139, half3(_2187)), dot(_1152, half3(_2187))) * _1158;
    half _2213 = half(1.0) / fma(_2140, _2140, dot(_2205, _2205));
    half _2254 = half(1.0) - clamp(dot(half3(_2049), half3(_2187)), half(0.0), half(1.0));
    half _2257 = _2254 * _2254;
    half3 _2168 = min(((half3(float3(params.facet_f0)) + (_1701 * ((_2257 * _2257) * _2254))) * min(((_1166 * _2213) * _2213) * min(half(64.0) / fma(_2136, _1182, _967 * length(half3(_1160 * half2(dot(_1139, half3(_2049)), dot(_1152, half3(_2049))), half(128.0) * _2136))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2058) * half(_2058)) / fast::max(_2044, 9.9999997473787516355514526367188e-05)) * half(_2077)) * half(_2077)), float3(65504.0))) * _2136), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2005 + _2168, half(1.0)));
    return out;
}

