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
    half3 _783 = normalize(half3(in.v_normal));
    float3 _789 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1056 = max(dot(_783, half3(_789)), half(9.9999997473787516355514526367188e-05));
    float4 _1095 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1056, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1114 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1095).y) - half(1.0)));
    float4 _1121 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_789), _783)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1166 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1169 = dot(_1166, _1166);
    float3 _1174 = _1166 * rsqrt(fast::max(_1169, 9.9999999392252902907785028219223e-09));
    float _1178 = _1169 * float(frame.punctualLights[0].positionFalloff.w);
    float _1183 = fast::clamp(fma(-_1178, _1178, 1.0), 0.0, 1.0);
    float _1202 = fast::clamp(fma(dot(-_1174, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1321 = fast::normalize(_789 + _1174);
    half _1265 = clamp(dot(_783, half3(_1174)), half(0.0), half(1.0));
    half _1361 = half(4096.0) * half(params.facet_alpha);
    half4 _1386 = half4(cross(_783, half3(_1321)), half(params.facet_alpha) * clamp(dot(_783, half3(_1321)), half(0.0), half(1.0))) * half(64.0);
    half _1367 = _1361 / dot(_1386, _1386);
    half _1397 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1403 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1407 = sqrt(fma(_1056 * _1056, _1403, _1397));
    half _1431 = half(1.0) - clamp(dot(half3(_1174), half3(_1321)), half(0.0), half(1.0));
    half _1434 = _1431 * _1431;
    half3 _1442 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1500 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1503 = dot(_1500, _1500);
    float3 _1508 = _1500 * rsqrt(fast::max(_1503, 9.9999999392252902907785028219223e-09));
    float _1512 = _1503 * float(frame.punctualLights[1].positionFalloff.w);
    float _1517 = fast::clamp(fma(-_1512, _1512, 1.0), 0.0, 1.0);
    float _1536 = fast::clamp(fma(dot(-_1508, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1655 = fast::normalize(_789 + _1508);
    half _1599 = clamp(dot(_783, half3(_1508)), half(0.0), half(1.0));
    half4 _1720 = half4(cross(_783, half3(_1655)), half(params.facet_alpha) * clamp(dot(_783, half3(_1655)), half(0.0), half(1.0))) * half(64.0);
    half _1701 = _1361 / dot(_1720, _1720);
    half _1765 = half(1.0) - clamp(dot(half3(_1508), half3(_1655)), half(0.0), half(1.0));
    half _1768 = _1765 * _1765;
    half3 _1798 = fma(half4(_1121).xyz, mix(half4(_1095).xxx, half4(_1095).yyy, half3(float3(params.facet_f0))) * _1114, min((((half3(float3(params.facet_f0)) + (_1442 * ((_1434 * _1434) * _1431))) * min(min((_1367 * _1367) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1265, _1407, _1056 * sqrt(fma(_1265 * _1265, _1403, _1397))), half(65504.0)), half(65504.0))) * _1114) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1183) * half(_1183)) / fast::max(_1169, 9.9999997473787516355514526367188e-05)) * half(_1202)) * half(_1202)), float3(65504.0))) * _1265), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1442 * ((_1768 * _1768) * _1765))) * min(min((_1701 * _1701) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1599, _1407, _1056 * sqrt(fma(_1599 * _1599, _1403, _1397))), half(65504.0)), half(65504.0))) * _1114) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1517) * half(_1517)) / fast::max(_1503, 9.9999997473787516355514526367188e-05)) * half(_1536)) * half(_1536)), float3(65504.0))) * _1599), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1798, half(1.0)));
    return out;
}

