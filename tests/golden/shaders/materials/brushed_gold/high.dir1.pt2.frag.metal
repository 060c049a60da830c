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
    half3 _765 = normalize(half3(in.v_normal));
    float3 _771 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1062 = max(dot(_765, half3(_771)), half(9.9999997473787516355514526367188e-05));
    float4 _1101 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1062, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1120 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1101).y) - half(1.0)));
    float4 _1127 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_771), _765)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1243 = fast::normalize(_771 + frame.lightDirection.xyz);
    half _1187 = clamp(dot(_765, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1283 = cross(_765, half3(_1243));
    half _1286 = clamp(dot(_765, half3(_1243)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1295 = half(params.facet_alpha) / fma(_1286, _1286, dot(_1283, _1283));
    half _1309 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1315 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1319 = sqrt(fma(_1062 * _1062, _1315, _1309));
    half _1343 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1243)), half(0.0), half(1.0));
    half _1346 = _1343 * _1343;
    half3 _1354 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1412 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1415 = dot(_1412, _1412);
    float3 _1420 = _1412 * rsqrt(fast::max(_1415, 9.9999999392252902907785028219223e-09));
    float _1424 = _1415 * float(frame.punctualLights[0].positionFalloff.w);
    float _1429 = fast::clamp(fma(-_1424, _1424, 1.0), 0.0, 1.0);
    float _1448 = fast::clamp(fma(dot(-_1420, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1567 = fast::normalize(_771 + _1420);
    half _1511 = clamp(dot(_765, half3(_1420)), half(0.0), half(1.0));
    half3 _1607 = cross(_765, half3(_1567));
    half _1610 = clamp(dot(_765, half3(_1567)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1619 = half(params.facet_alpha) / fma(_1610, _1610, dot(_1607, _1607));
    half _1667 = half(1.0) - clamp(dot(half3(_1420), half3(_1567)), half(0.0), half(1.0));
    half _1670 = _1667 * _1667;
    float3 _1736 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1739 = dot(_1736, _1736);
    float3 _1744 = _1736 * rsqrt(fast::max(_1739, 9.9999999392252902907785028219223e-09));
    float _1748 = _1739 * float(frame.punctualLights[1].positionFalloff.w);
    float _1753 = fast::clamp(fma(-_1748, _1748, 1.0), 0.0, 1.0);
    float _1772 = fast::clamp(fma(dot(-_1744, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1891 = fast::normalize(_771 + _1744);
    half _1835 = clamp(dot(_765, half3(_1744)), half(0.0), half(1.0));
    half3 _1931 = cross(_765, half3(_1891));
    half _1934 = clamp(dot(_765, half3(_1891)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1943 = half(params.facet_alpha) / fma(_1934, _1934, dot(_1931, _1931));
    half _1991 = half(1.0) - clamp(dot(half3(_1744), half3(_1891)), half(0.0), half(1.0));
    half _1994 = _1991 * _1991;
    half3 _2024 = (fma(half4(_1127).xyz, mix(half4(_1101).xxx, half4(_1101).yyy, half3(float3(params.facet_f0))) * _1120, min((((half3(float3(params.facet_f0)) + (_1354 * ((_1346 * _1346) * _1343))) * min(min((_1295 * _1295) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1187, _1319, _1062 * sqrt(fma(_1187 * _1187, _1315, _1309))), half(65504.0)), half(65504.0))) * _1120) * (half4(frame.lightColor).xyz * _1187), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1354 * ((_1670 * _1670) * _1667))) * min(min((_1619 * _1619) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1511, _1319, _1062 * sqrt(fma(_1511 * _1511, _1315, _1309))), half(65504.0)), half(65504.0))) * _1120) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1429) * half(_1429)) / fast::max(_1415, 9.9999997473787516355514526367188e-05)) * half(_1448)) * half(_1448)), float3(65504.0))) * _1511), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1354 * ((_1994 * _1994) * _1991))) * min(min((_1943 * _1943) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1835, _1319, _1062 * sqrt(fma(_1835 * _1835, _1315, _1309))), half(65504.0)), half(65504.0))) * _1120) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1753) * half(_1753)) / fast::max(_1739, 9.9999997473787516355514526367188e-05)) * half(_1772)) * half(_1772)), float3(65504.0))) * _1835), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2024, half(1.0)));
    return out;
}

