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
    half3 _675 = normalize(half3(in.v_normal));
    float3 _681 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _879 = max(dot(_675, half3(_681)), half(9.9999997473787516355514526367188e-05));
    float4 _918 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_879, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _937 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_918).y) - half(1.0)));
    float4 _944 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_681), _675)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _989 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _992 = dot(_989, _989);
    float3 _997 = _989 * rsqrt(fast::max(_992, 9.9999999392252902907785028219223e-09));
    float _1001 = _992 * float(frame.punctualLights[0].positionFalloff.w);
    float _1006 = fast::clamp(fma(-_1001, _1001, 1.0), 0.0, 1.0);
    float _1025 = fast::clamp(fma(dot(-_997, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1144 = fast::normalize(_681 + _997);
    half _1088 = clamp(dot(_675, half3(_997)), half(0.0), half(1.0));
    half3 _1184 = cross(_675, half3(_1144));
    half _1187 = clamp(dot(_675, half3(_1144)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1196 = half(params.facet_alpha) / fma(_1187, _1187, dot(_1184, _1184));
    half _1224 = half(1.0) - clamp(dot(half3(_997), half3(_1144)), half(0.0), half(1.0));
    half _1227 = _1224 * _1224;
    half3 _1235 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1293 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1296 = dot(_1293, _1293);
    float3 _1301 = _1293 * rsqrt(fast::max(_1296, 9.9999999392252902907785028219223e-09));
    float _1305 = _1296 * float(frame.punctualLights[1].positionFalloff.w);
    float _1310 = fast::clamp(fma(-_1305, _1305, 1.0), 0.0, 1.0);
    float _1329 = fast::clamp(fma(dot(-_1301, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1448 = fast::normalize(_681 + _1301);
    half _1392 = clamp(dot(_675, half3(_1301)), half(0.0), half(1.0));
    half3 _1488 = cross(_675, half3(_1448));
    half _1491 = clamp(dot(_675, half3(_1448)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1500 = half(params.facet_alpha) / fma(_1491, _1491, dot(_1488, _1488));
    half _1528 = half(1.0) - clamp(dot(half3(_1301), half3(_1448)), half(0.0), half(1.0));
    half _1531 = _1528 * _1528;
    half3 _1561 = fma(half4(_944).xyz, mix(half4(_918).xxx, half4(_918).yyy, half3(float3(params.facet_f0))) * _937, min((((half3(float3(params.facet_f0)) + (_1235 * ((_1227 * _1227) * _1224))) * min(min((_1196 * _1196) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1088) * _879, _1088 + _879, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * _937) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1006) * half(_1006)) / fast::max(_992, 9.9999997473787516355514526367188e-05)) * half(_1025)) * half(_1025)), float3(65504.0))) * _1088), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1235 * ((_1531 * _1531) * _1528))) * min(min((_1500 * _1500) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1392) * _879, _1392 + _879, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * _937) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1310) * half(_1310)) / fast::max(_1296, 9.9999997473787516355514526367188e-05)) * half(_1329)) * half(_1329)), float3(65504.0))) * _1392), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1561, half(1.0)));
    return out;
}

