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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _656 = normalize(half3(in.v_normal));
    float3 _672 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _817 = half4(in.v_tangent).xyz;
    half _870 = max(dot(_656, half3(_672)), half(9.9999997473787516355514526367188e-05));
    half _979 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half3 _1746;
    if (float(_979) >= 0.0)
    {
        _1746 = _817;
    }
    else
    {
        _1746 = cross(_656, _817);
    }
    half _931 = dot(_1746, half3(_672));
    half _938 = min(abs(_979) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _943 = fma(half(-float(_938)), half(1.0) - _870, half(1.0));
    half _946 = _938 * _931;
    float4 _986 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_870, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1012 = facet_environment.sample(facet_environmentSmplr, float3(((((_656 * _943) + (_1746 * _946)) * (half(512.0) * fma(_943, _870, _946 * _931))) - (half3(_672) * (half(256.0) * fma(_943, _943, _946 * _946))))), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _891 = mix(half4(_986).xxx, half4(_986).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_986).y) - half(1.0))));
    half3 _714 = half4(frame.lightDirection).xyz;
    half3 _1125 = reflect(-half3(_672), _656);
    half _1141 = clamp(dot(_1125, _714), half(0.0), half(1.0));
    half _1144 = _1141 * _1141;
    half4 _1808 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1144 * _1144, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1156 = _1808.x;
    float3 _1201 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1204 = dot(_1201, _1201);
    float3 _1209 = _1201 * rsqrt(fast::max(_1204, 9.9999999392252902907785028219223e-09));
    float _1213 = _1204 * float(frame.punctualLights[0].positionFalloff.w);
    float _1218 = fast::clamp(fma(-_1213, _1213, 1.0), 0.0, 1.0);
    float _1237 = fast::clamp(fma(dot(-_1209, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1369 = clamp(dot(_1125, half3(_1209)), half(0.0), half(1.0));
    half _1372 = _1369 * _1369;
    half4 _1833 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1372 * _1372, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1384 = _1833.x;
    float3 _1429 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1432 = dot(_1429, _1429);
    float3 _1437 = _1429 * rsqrt(fast::max(_1432, 9.9999999392252902907785028219223e-09));
    float _1441 = _1432 * float(frame.punctualLights[1].positionFalloff.w);
    float _1446 = fast::clamp(fma(-_1441, _1441, 1.0), 0.0, 1.0);
    float _1465 = fast::clamp(fma(dot(-_1437, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1597 = clamp(dot(_1125, half3(_1437)), half(0.0), half(1.0));
    half _1600 = _1597 * _1597;
    half4 _1859 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1600 * _1600, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1612 = _1859.x;
    half3 _1621 = (fma(half4(_1012).xyz, _891, min((_891 * ((_1156 * _1156) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_656, _714), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_891 * ((_1384 * _1384) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1218) * half(_1218)) / fast::max(_1204, 9.9999997473787516355514526367188e-05)) * half(_1237)) * half(_1237)), float3(65504.0))) * clamp(dot(_656, half3(_1209)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_891 * ((_1612 * _1612) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1446) * half(_1446)) / fast::max(_1432, 9.9999997473787516355514526367188e-05)) * half(_1465)) * half(_1465)), float3(65504.0))) * clamp(dot(_656, half3(_1437)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1621, half(1.0)));
    return out;
}

