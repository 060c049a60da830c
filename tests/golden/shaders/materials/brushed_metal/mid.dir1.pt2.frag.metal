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
    half3 _675 = normalize(half3(in.v_normal));
    float3 _691 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _833 = half4(in.v_tangent).xyz;
    half _886 = max(dot(_675, half3(_691)), half(9.9999997473787516355514526367188e-05));
    half _994 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half3 _1821;
    if (float(_994) >= 0.0)
    {
        _1821 = _833;
    }
    else
    {
        _1821 = cross(_675, _833);
    }
    half _946 = dot(_1821, half3(_691));
    half _953 = min(abs(_994) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _958 = fma(half(-float(_953)), half(1.0) - _886, half(1.0));
    half _961 = _953 * _946;
    float4 _1001 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_886, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1020 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1001).y) - half(1.0)));
    float4 _1027 = facet_environment.sample(facet_environmentSmplr, float3(((((_675 * _958) + (_1821 * _961)) * (half(512.0) * fma(_958, _886, _961 * _946))) - (half3(_691) * (half(256.0) * fma(_958, _958, _961 * _961))))), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _733 = half4(frame.lightDirection).xyz;
    half3 _1134 = normalize(half3(_691) + _733);
    half _1085 = clamp(dot(_675, _733), half(0.0), half(1.0));
    half3 _1161 = cross(_675, _1134);
    half _1164 = clamp(dot(_675, _1134), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1181 = max(mix((half(2.0) * _1085) * _886, _1085 + _886, half(params.facet_alpha)), half(0.000244140625));
    half _1183 = half(1024.0) * half(params.facet_alpha);
    half _1188 = _1183 / (fma(_1164, _1164, dot(_1161, _1161)) * (half(6433.98193359375) * _1181));
    float3 _1236 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1239 = dot(_1236, _1236);
    float3 _1244 = _1236 * rsqrt(fast::max(_1239, 9.9999999392252902907785028219223e-09));
    float _1248 = _1239 * float(frame.punctualLights[0].positionFalloff.w);
    float _1253 = fast::clamp(fma(-_1248, _1248, 1.0), 0.0, 1.0);
    float _1272 = fast::clamp(fma(dot(-_1244, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1382 = normalize(half3(_691) + half3(_1244));
    half _1333 = clamp(dot(_675, half3(_1244)), half(0.0), half(1.0));
    half3 _1409 = cross(_675, _1382);
    half _1412 = clamp(dot(_675, _1382), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1429 = max(mix((half(2.0) * _1333) * _886, _1333 + _886, half(params.facet_alpha)), half(0.000244140625));
    half _1436 = _1183 / (fma(_1412, _1412, dot(_1409, _1409)) * (half(6433.98193359375) * _1429));
    float3 _1484 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1487 = dot(_1484, _1484);
    float3 _1492 = _1484 * rsqrt(fast::max(_1487, 9.9999999392252902907785028219223e-09));
    float _1496 = _1487 * float(frame.punctualLights[1].positionFalloff.w);
    float _1501 = fast::clamp(fma(-_1496, _1496, 1.0), 0.0, 1.0);
    float _1520 = fast::clamp(fma(dot(-_1492, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1630 = normalize(half3(_691) + half3(_1492));
    half _1581 = clamp(dot(_675, half3(_1492)), half(0.0), half(1.0));
    half3 _1657 = cross(_675, _1630);
    half _1660 = clamp(dot(_675, _1630), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1677 = max(mix((half(2.0) * _1581) * _886, _1581 + _886, half(params.facet_alpha)), half(0.000244140625));
    half _1684 = _1183 / (fma(_1660, _1660, dot(_1657, _1657)) * (half(6433.98193359375) * _1677));
    half3 _1696 = (fma(half4(_1027).xyz, mix(half4(_1001).xxx, half4(_1001).yyy, half3(float3(params.facet_f0))) * _1020, min(((half3(float3(params.facet_f0)) * min(_1188 * (_1188 * (half(6.283185482025146484375) * _1181)), half(65504.0))) * _1020) * (half4(frame.lightColor).xyz * _1085), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1436 * (_1436 * (half(6.283185482025146484375) * _1429)), half(65504.0))) * _1020) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1253) * half(_1253)) / fast::max(_1239, 9.9999997473787516355514526367188e-05)) * half(_1272)) * half(_1272)), float3(65504.0))) * _1333), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1684 * (_1684 * (half(6.283185482025146484375) * _1677)), half(65504.0))) * _1020) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1501) * half(_1501)) / fast::max(_1487, 9.9999997473787516355514526367188e-05)) * half(_1520)) * half(_1520)), float3(65504.0))) * _1581), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1696, half(1.0)));
    return out;
}

