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
    half3 _769 = normalize(half3(in.v_normal));
    float3 _775 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1063 = max(dot(_769, half3(_775)), half(9.9999997473787516355514526367188e-05));
    float4 _1102 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1063, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1121 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1102).y) - half(1.0)));
    float4 _1131 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_775), _769)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1247 = fast::normalize(_775 + frame.lightDirection.xyz);
    half _1191 = clamp(dot(_769, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1287 = cross(_769, half3(_1247));
    half _1290 = clamp(dot(_769, half3(_1247)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1299 = half(params.facet_alpha) / fma(_1290, _1290, dot(_1287, _1287));
    half _1313 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1319 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1323 = sqrt(fma(_1063 * _1063, _1319, _1313));
    half _1347 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1247)), half(0.0), half(1.0));
    half _1350 = _1347 * _1347;
    half3 _1358 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1416 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1419 = dot(_1416, _1416);
    float3 _1424 = _1416 * rsqrt(fast::max(_1419, 9.9999999392252902907785028219223e-09));
    float _1428 = _1419 * float(frame.punctualLights[0].positionFalloff.w);
    float _1433 = fast::clamp(fma(-_1428, _1428, 1.0), 0.0, 1.0);
    float _1452 = fast::clamp(fma(dot(-_1424, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1571 = fast::normalize(_775 + _1424);
    half _1515 = clamp(dot(_769, half3(_1424)), half(0.0), half(1.0));
    half3 _1611 = cross(_769, half3(_1571));
    half _1614 = clamp(dot(_769, half3(_1571)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1623 = half(params.facet_alpha) / fma(_1614, _1614, dot(_1611, _1611));
    half _1671 = half(1.0) - clamp(dot(half3(_1424), half3(_1571)), half(0.0), half(1.0));
    half _1674 = _1671 * _1671;
    float3 _1740 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1743 = dot(_1740, _1740);
    float3 _1748 = _1740 * rsqrt(fast::max(_1743, 9.9999999392252902907785028219223e-09));
    float _1752 = _1743 * float(frame.punctualLights[1].positionFalloff.w);
    float _1757 = fast::clamp(fma(-_1752, _1752, 1.0), 0.0, 1.0);
    float _1776 = fast::clamp(fma(dot(-_1748, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1895 = fast::normalize(_775 + _1748);
    half _1839 = clamp(dot(_769, half3(_1748)), half(0.0), half(1.0));
    half3 _1935 = cross(_769, half3(_1895));
    half _1938 = clamp(dot(_769, half3(_1895)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1947 = half(params.facet_alpha) / fma(_1938, _1938, dot(_1935, _1935));
    half _1995 = half(1.0) - clamp(dot(half3(_1748), half3(_1895)), half(0.0), half(1.0));
    half _1998 = _1995 * _1995;
    half3 _2028 = (fma(half4(_1131).xyz, mix(half4(_1102).xxx, half4(_1102).yyy, half3(float3(params.facet_f0))) * _1121, min((((half3(float3(params.facet_f0)) + (_1358 * ((_1350 * _1350) * _1347))) * min(min((_1299 * _1299) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1191, _1323, _1063 * sqrt(fma(_1191 * _1191, _1319, _1313))), half(65504.0)), half(65504.0))) * _1121) * (half4(frame.lightColor).xyz * _1191), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1358 * ((_1674 * _1674) * _1671))) * min(min((_1623 * _1623) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1515, _1323, _1063 * sqrt(fma(_1515 * _1515, _1319, _1313))), half(65504.0)), half(65504.0))) * _1121) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1433) * half(_1433)) / fast::max(_1419, 9.9999997473787516355514526367188e-05)) * half(_1452)) * half(_1452)), float3(65504.0))) * _1515), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1358 * ((_1998 * _1998) * _1995))) * min(min((_1947 * _1947) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1839, _1323, _1063 * sqrt(fma(_1839 * _1839, _1319, _1313))), half(65504.0)), half(65504.0))) * _1121) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1757) * half(_1757)) / fast::max(_1743, 9.9999997473787516355514526367188e-05)) * half(_1776)) * half(_1776)), float3(65504.0))) * _1839), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2028, half(1.0)));
    return out;
}

