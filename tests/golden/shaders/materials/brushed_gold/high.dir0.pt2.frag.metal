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
    half _1038 = max(dot(_765, half3(_771)), half(9.9999997473787516355514526367188e-05));
    float4 _1077 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1038, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1096 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1077).y) - half(1.0)));
    float4 _1103 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_771), _765)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1148 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1151 = dot(_1148, _1148);
    float3 _1156 = _1148 * rsqrt(fast::max(_1151, 9.9999999392252902907785028219223e-09));
    float _1160 = _1151 * float(frame.punctualLights[0].positionFalloff.w);
    float _1165 = fast::clamp(fma(-_1160, _1160, 1.0), 0.0, 1.0);
    float _1184 = fast::clamp(fma(dot(-_1156, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1303 = fast::normalize(_771 + _1156);
    half _1247 = clamp(dot(_765, half3(_1156)), half(0.0), half(1.0));
    half3 _1343 = cross(_765, half3(_1303));
    half _1346 = clamp(dot(_765, half3(_1303)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1355 = half(params.facet_alpha) / fma(_1346, _1346, dot(_1343, _1343));
    half _1369 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1375 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1379 = sqrt(fma(_1038 * _1038, _1375, _1369));
    half _1403 = half(1.0) - clamp(dot(half3(_1156), half3(_1303)), half(0.0), half(1.0));
    half _1406 = _1403 * _1403;
    half3 _1414 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1472 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1475 = dot(_1472, _1472);
    float3 _1480 = _1472 * rsqrt(fast::max(_1475, 9.9999999392252902907785028219223e-09));
    float _1484 = _1475 * float(frame.punctualLights[1].positionFalloff.w);
    float _1489 = fast::clamp(fma(-_1484, _1484, 1.0), 0.0, 1.0);
    float _1508 = fast::clamp(fma(dot(-_1480, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1627 = fast::normalize(_771 + _1480);
    half _1571 = clamp(dot(_765, half3(_1480)), half(0.0), half(1.0));
    half3 _1667 = cross(_765, half3(_1627));
    half _1670 = clamp(dot(_765, half3(_1627)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1679 = half(params.facet_alpha) / fma(_1670, _1670, dot(_1667, _1667));
    half _1727 = half(1.0) - clamp(dot(half3(_1480), half3(_1627)), half(0.0), half(1.0));
    half _1730 = _1727 * _1727;
    half3 _1760 = fma(half4(_1103).xyz, mix(half4(_1077).xxx, half4(_1077).yyy, half3(float3(params.facet_f0))) * _1096, min((((half3(float3(params.facet_f0)) + (_1414 * ((_1406 * _1406) * _1403))) * min(min((_1355 * _1355) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1247, _1379, _1038 * sqrt(fma(_1247 * _1247, _1375, _1369))), half(65504.0)), half(65504.0))) * _1096) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1165) * half(_1165)) / fast::max(_1151, 9.9999997473787516355514526367188e-05)) * half(_1184)) * half(_1184)), float3(65504.0))) * _1247), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1414 * ((_1730 * _1730) * _1727))) * min(min((_1679 * _1679) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1571, _1379, _1038 * sqrt(fma(_1571 * _1571, _1375, _1369))), half(65504.0)), half(65504.0))) * _1096) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1489) * half(_1489)) / fast::max(_1475, 9.9999997473787516355514526367188e-05)) * half(_1508)) * half(_1508)), float3(65504.0))) * _1571), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1760, half(1.0)));
    return out;
}

