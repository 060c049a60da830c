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
    half3 _696 = normalize(half3(in.v_normal));
    float3 _702 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _921 = max(dot(_696, half3(_702)), half(9.9999997473787516355514526367188e-05));
    float4 _960 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_921, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _979 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_960).y) - half(1.0)));
    float4 _989 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_702), _696)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1105 = fast::normalize(_702 + frame.lightDirection.xyz);
    half _1049 = clamp(dot(_696, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1145 = half(4096.0) * half(params.facet_alpha);
    half4 _1170 = half4(cross(_696, half3(_1105)), half(params.facet_alpha) * clamp(dot(_696, half3(_1105)), half(0.0), half(1.0))) * half(64.0);
    half _1151 = _1145 / dot(_1170, _1170);
    half _1195 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1105)), half(0.0), half(1.0));
    half _1198 = _1195 * _1195;
    half3 _1206 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1264 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1267 = dot(_1264, _1264);
    float3 _1272 = _1264 * rsqrt(fast::max(_1267, 9.9999999392252902907785028219223e-09));
    float _1276 = _1267 * float(frame.punctualLights[0].positionFalloff.w);
    float _1281 = fast::clamp(fma(-_1276, _1276, 1.0), 0.0, 1.0);
    float _1300 = fast::clamp(fma(dot(-_1272, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1419 = fast::normalize(_702 + _1272);
    half _1363 = clamp(dot(_696, half3(_1272)), half(0.0), half(1.0));
    half4 _1484 = half4(cross(_696, half3(_1419)), half(params.facet_alpha) * clamp(dot(_696, half3(_1419)), half(0.0), half(1.0))) * half(64.0);
    half _1465 = _1145 / dot(_1484, _1484);
    half _1509 = half(1.0) - clamp(dot(half3(_1272), half3(_1419)), half(0.0), half(1.0));
    half _1512 = _1509 * _1509;
    float3 _1578 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1581 = dot(_1578, _1578);
    float3 _1586 = _1578 * rsqrt(fast::max(_1581, 9.9999999392252902907785028219223e-09));
    float _1590 = _1581 * float(frame.punctualLights[1].positionFalloff.w);
    float _1595 = fast::clamp(fma(-_1590, _1590, 1.0), 0.0, 1.0);
    float _1614 = fast::clamp(fma(dot(-_1586, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1733 = fast::normalize(_702 + _1586);
    half _1677 = clamp(dot(_696, half3(_1586)), half(0.0), half(1.0));
    half4 _1798 = half4(cross(_696, half3(_1733)), half(params.facet_alpha) * clamp(dot(_696, half3(_1733)), half(0.0), half(1.0))) * half(64.0);
    half _1779 = _1145 / dot(_1798, _1798);
    half _1823 = half(1.0) - clamp(dot(half3(_1586), half3(_1733)), half(0.0), half(1.0));
    half _1826 = _1823 * _1823;
    half3 _1856 = (fma(half4(_989).xyz, mix(half4(_960).xxx, half4(_960).yyy, half3(float3(params.facet_f0))) * _979, min((((half3(float3(params.facet_f0)) + (_1206 * ((_1198 * _1198) * _1195))) * min(min((_1151 * _1151) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1049) * _921, _1049 + _921, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * _979) * (half4(frame.lightColor).xyz * _1049), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1206 * ((_1512 * _1512) * _1509))) * min(min((_1465 * _1465) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1363) * _921, _1363 + _921, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * _979) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1281) * half(_1281)) / fast::max(_1267, 9.9999997473787516355514526367188e-05)) * half(_1300)) * half(_1300)), float3(65504.0))) * _1363), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1206 * ((_1826 * _1826) * _1823))) * min(min((_1779 * _1779) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1677) * _921, _1677 + _921, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * _979) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1595) * half(_1595)) / fast::max(_1581, 9.9999997473787516355514526367188e-05)) * half(_1614)) * half(_1614)), float3(65504.0))) * _1677), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1856, half(1.0)));
    return out;
}

