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
    half _1041 = max(dot(_765, half3(_771)), half(9.9999997473787516355514526367188e-05));
    float4 _1080 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1041, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1099 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1080).y) - half(1.0)));
    float4 _1106 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_771), _765)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1151 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1154 = dot(_1151, _1151);
    float3 _1159 = _1151 * rsqrt(fast::max(_1154, 9.9999999392252902907785028219223e-09));
    float _1163 = _1154 * float(frame.punctualLights[0].positionFalloff.w);
    float _1168 = fast::clamp(fma(-_1163, _1163, 1.0), 0.0, 1.0);
    float _1187 = fast::clamp(fma(dot(-_1159, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1306 = fast::normalize(_771 + _1159);
    half _1250 = clamp(dot(_765, half3(_1159)), half(0.0), half(1.0));
    half3 _1346 = cross(_765, half3(_1306));
    half _1349 = clamp(dot(_765, half3(_1306)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1358 = half(params.facet_alpha) / fma(_1349, _1349, dot(_1346, _1346));
    half _1372 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1378 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1382 = sqrt(fma(_1041 * _1041, _1378, _1372));
    half _1406 = half(1.0) - clamp(dot(half3(_1159), half3(_1306)), half(0.0), half(1.0));
    half _1409 = _1406 * _1406;
    half3 _1417 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1475 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1478 = dot(_1475, _1475);
    float3 _1483 = _1475 * rsqrt(fast::max(_1478, 9.9999999392252902907785028219223e-09));
    float _1487 = _1478 * float(frame.punctualLights[1].positionFalloff.w);
    float _1492 = fast::clamp(fma(-_1487, _1487, 1.0), 0.0, 1.0);
    float _1511 = fast::clamp(fma(dot(-_1483, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1630 = fast::normalize(_771 + _1483);
    half _1574 = clamp(dot(_765, half3(_1483)), half(0.0), half(1.0));
    half3 _1670 = cross(_765, half3(_1630));
    half _1673 = clamp(dot(_765, half3(_1630)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1682 = half(params.facet_alpha) / fma(_1673, _1673, dot(_1670, _1670));
    half _1730 = half(1.0) - clamp(dot(half3(_1483), half3(_1630)), half(0.0), half(1.0));
    half _1733 = _1730 * _1730;
    half3 _1763 = fma(half4(_1106).xyz, mix(half4(_1080).xxx, half4(_1080).yyy, half3(float3(params.facet_f0))) * _1099, min((((half3(float3(params.facet_f0)) + (_1417 * ((_1409 * _1409) * _1406))) * min(min((_1358 * _1358) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1250, _1382, _1041 * sqrt(fma(_1250 * _1250, _1378, _1372))), half(65504.0)), half(65504.0))) * _1099) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1168) * half(_1168)) / fast::max(_1154, 9.9999997473787516355514526367188e-05)) * half(_1187)) * half(_1187)), float3(65504.0))) * _1250), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1417 * ((_1733 * _1733) * _1730))) * min(min((_1682 * _1682) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1574, _1382, _1041 * sqrt(fma(_1574 * _1574, _1378, _1372))), half(65504.0)), half(65504.0))) * _1099) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1492) * half(_1492)) / fast::max(_1478, 9.9999997473787516355514526367188e-05)) * half(_1511)) * half(_1511)), float3(65504.0))) * _1574), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1763, half(1.0)));
    return out;
}

