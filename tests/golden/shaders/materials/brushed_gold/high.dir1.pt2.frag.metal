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
    half3 _787 = normalize(half3(in.v_normal));
    float3 _793 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1081 = max(dot(_787, half3(_793)), half(9.9999997473787516355514526367188e-05));
    float4 _1120 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1081, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1139 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1120).y) - half(1.0)));
    float4 _1149 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_793), _787)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1265 = fast::normalize(_793 + frame.lightDirection.xyz);
    half _1209 = clamp(dot(_787, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1305 = half(4096.0) * half(params.facet_alpha);
    half4 _1330 = half4(cross(_787, half3(_1265)), half(params.facet_alpha) * clamp(dot(_787, half3(_1265)), half(0.0), half(1.0))) * half(64.0);
    half _1311 = _1305 / dot(_1330, _1330);
    half _1341 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1347 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1351 = sqrt(fma(_1081 * _1081, _1347, _1341));
    half _1375 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1265)), half(0.0), half(1.0));
    half _1378 = _1375 * _1375;
    half3 _1386 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1444 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1447 = dot(_1444, _1444);
    float3 _1452 = _1444 * rsqrt(fast::max(_1447, 9.9999999392252902907785028219223e-09));
    float _1456 = _1447 * float(frame.punctualLights[0].positionFalloff.w);
    float _1461 = fast::clamp(fma(-_1456, _1456, 1.0), 0.0, 1.0);
    float _1480 = fast::clamp(fma(dot(-_1452, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1599 = fast::normalize(_793 + _1452);
    half _1543 = clamp(dot(_787, half3(_1452)), half(0.0), half(1.0));
    half4 _1664 = half4(cross(_787, half3(_1599)), half(params.facet_alpha) * clamp(dot(_787, half3(_1599)), half(0.0), half(1.0))) * half(64.0);
    half _1645 = _1305 / dot(_1664, _1664);
    half _1709 = half(1.0) - clamp(dot(half3(_1452), half3(_1599)), half(0.0), half(1.0));
    half _1712 = _1709 * _1709;
    float3 _1778 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1781 = dot(_1778, _1778);
    float3 _1786 = _1778 * rsqrt(fast::max(_1781, 9.9999999392252902907785028219223e-09));
    float _1790 = _1781 * float(frame.punctualLights[1].positionFalloff.w);
    float _1795 = fast::clamp(fma(-_1790, _1790, 1.0), 0.0, 1.0);
    float _1814 = fast::clamp(fma(dot(-_1786, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1933 = fast::normalize(_793 + _1786);
    half _1877 = clamp(dot(_787, half3(_1786)), half(0.0), half(1.0));
    half4 _1998 = half4(cross(_787, half3(_1933)), half(params.facet_alpha) * clamp(dot(_787, half3(_1933)), half(0.0), half(1.0))) * half(64.0);
    half _1979 = _1305 / dot(_1998, _1998);
    half _2043 = half(1.0) - clamp(dot(half3(_1786), half3(_1933)), half(0.0), half(1.0));
    half _2046 = _2043 * _2043;
    half3 _2076 = (fma(half4(_1149).xyz, mix(half4(_1120).xxx, half4(_1120).yyy, half3(float3(params.facet_f0))) * _1139, min((((half3(float3(params.facet_f0)) + (_1386 * ((_1378 * _1378) * _1375))) * min(min((_1311 * _1311) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1209, _1351, _1081 * sqrt(fma(_1209 * _1209, _1347, _1341))), half(65504.0)), half(65504.0))) * _1139) * (half4(frame.lightColor).xyz * _1209), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1386 * ((_1712 * _1712) * _1709))) * min(min((_1645 * _1645) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1543, _1351, _1081 * sqrt(fma(_1543 * _1543, _1347, _1341))), half(65504.0)), half(65504.0))) * _1139) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1461) * half(_1461)) / fast::max(_1447, 9.9999997473787516355514526367188e-05)) * half(_1480)) * half(_1480)), float3(65504.0))) * _1543), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1386 * ((_2046 * _2046) * _2043))) * min(min((_1979 * _1979) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1877, _1351, _1081 * sqrt(fma(_1877 * _1877, _1347, _1341))), half(65504.0)), half(65504.0))) * _1139) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1795) * half(_1795)) / fast::max(_1781, 9.9999997473787516355514526367188e-05)) * half(_1814)) * half(_1814)), float3(65504.0))) * _1877), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2076, half(1.0)));
    return out;
}

