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
    half _1042 = max(dot(_769, half3(_775)), half(9.9999997473787516355514526367188e-05));
    float4 _1081 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1042, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1100 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1081).y) - half(1.0)));
    float4 _1110 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_775), _769)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1155 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1158 = dot(_1155, _1155);
    float3 _1163 = _1155 * rsqrt(fast::max(_1158, 9.9999999392252902907785028219223e-09));
    float _1167 = _1158 * float(frame.punctualLights[0].positionFalloff.w);
    float _1172 = fast::clamp(fma(-_1167, _1167, 1.0), 0.0, 1.0);
    float _1191 = fast::clamp(fma(dot(-_1163, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1310 = fast::normalize(_775 + _1163);
    half _1254 = clamp(dot(_769, half3(_1163)), half(0.0), half(1.0));
    half3 _1350 = cross(_769, half3(_1310));
    half _1353 = clamp(dot(_769, half3(_1310)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1362 = half(params.facet_alpha) / fma(_1353, _1353, dot(_1350, _1350));
    half _1376 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1382 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1386 = sqrt(fma(_1042 * _1042, _1382, _1376));
    half _1410 = half(1.0) - clamp(dot(half3(_1163), half3(_1310)), half(0.0), half(1.0));
    half _1413 = _1410 * _1410;
    half3 _1421 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1479 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1482 = dot(_1479, _1479);
    float3 _1487 = _1479 * rsqrt(fast::max(_1482, 9.9999999392252902907785028219223e-09));
    float _1491 = _1482 * float(frame.punctualLights[1].positionFalloff.w);
    float _1496 = fast::clamp(fma(-_1491, _1491, 1.0), 0.0, 1.0);
    float _1515 = fast::clamp(fma(dot(-_1487, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1634 = fast::normalize(_775 + _1487);
    half _1578 = clamp(dot(_769, half3(_1487)), half(0.0), half(1.0));
    half3 _1674 = cross(_769, half3(_1634));
    half _1677 = clamp(dot(_769, half3(_1634)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1686 = half(params.facet_alpha) / fma(_1677, _1677, dot(_1674, _1674));
    half _1734 = half(1.0) - clamp(dot(half3(_1487), half3(_1634)), half(0.0), half(1.0));
    half _1737 = _1734 * _1734;
    half3 _1767 = fma(half4(_1110).xyz, mix(half4(_1081).xxx, half4(_1081).yyy, half3(float3(params.facet_f0))) * _1100, min((((half3(float3(params.facet_f0)) + (_1421 * ((_1413 * _1413) * _1410))) * min(min((_1362 * _1362) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1254, _1386, _1042 * sqrt(fma(_1254 * _1254, _1382, _1376))), half(65504.0)), half(65504.0))) * _1100) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1172) * half(_1172)) / fast::max(_1158, 9.9999997473787516355514526367188e-05)) * half(_1191)) * half(_1191)), float3(65504.0))) * _1254), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1421 * ((_1737 * _1737) * _1734))) * min(min((_1686 * _1686) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1578, _1386, _1042 * sqrt(fma(_1578 * _1578, _1382, _1376))), half(65504.0)), half(65504.0))) * _1100) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1496) * half(_1496)) / fast::max(_1482, 9.9999997473787516355514526367188e-05)) * half(_1515)) * half(_1515)), float3(65504.0))) * _1578), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1767, half(1.0)));
    return out;
}

