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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    half3 _681 = normalize(half3(in.v_normal));
    float3 _687 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _883 = max(dot(_681, half3(_687)), half(9.9999997473787516355514526367188e-05));
    float4 _925 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_883, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _944 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_925).y) - half(1.0)));
    float4 _901 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_687), _681)), level(params.facet_environmentLod));
    float3 _988 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _991 = dot(_988, _988);
    float3 _996 = _988 * rsqrt(fast::max(_991, 9.9999999392252902907785028219223e-09));
    float _1000 = _991 * float(frame.punctualLights[0].positionFalloff.w);
    float _1005 = fast::clamp(fma(-_1000, _1000, 1.0), 0.0, 1.0);
    float _1024 = fast::clamp(fma(dot(-_996, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1084 = clamp(dot(_681, half3(_996)), half(0.0), half(1.0));
    float3 _1143 = fast::normalize(_687 + _996);
    half _1183 = half(4096.0) * half(params.facet_alpha);
    half4 _1208 = half4(cross(_681, half3(_1143)), half(params.facet_alpha) * clamp(dot(_681, half3(_1143)), half(0.0), half(1.0))) * half(64.0);
    half _1189 = _1183 / dot(_1208, _1208);
    half _1233 = half(1.0) - clamp(dot(half3(_996), half3(_1143)), half(0.0), half(1.0));
    half _1236 = _1233 * _1233;
    half3 _1244 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1302 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1305 = dot(_1302, _1302);
    float3 _1310 = _1302 * rsqrt(fast::max(_1305, 9.9999999392252902907785028219223e-09));
    float _1314 = _1305 * float(frame.punctualLights[1].positionFalloff.w);
    float _1319 = fast::clamp(fma(-_1314, _1314, 1.0), 0.0, 1.0);
    float _1338 = fast::clamp(fma(dot(-_1310, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1398 = clamp(dot(_681, half3(_1310)), half(0.0), half(1.0));
    float3 _1457 = fast::normalize(_687 + _1310);
    half4 _1522 = half4(cross(_681, half3(_1457)), half(params.facet_alpha) * clamp(dot(_681, half3(_1457)), half(0.0), half(1.0))) * half(64.0);
    half _1503 = _1183 / dot(_1522, _1522);
    half _1547 = half(1.0) - clamp(dot(half3(_1310), half3(_1457)), half(0.0), half(1.0));
    half _1550 = _1547 * _1547;
    half3 _1580 = fma(half4(_901).xyz, mix(half4(_925).xxx, half4(_925).yyy, half3(float3(params.facet_f0))) * _944, min((((half3(float3(params.facet_f0)) + (_1244 * ((_1236 * _1236) * _1233))) * min(min((_1189 * _1189) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1084) * _883, _1084 + _883, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * _944) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1005) * half(_1005)) / fast::max(_991, 9.9999997473787516355514526367188e-05)) * half(_1024)) * half(_1024)), float3(65504.0))) * _1084), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1244 * ((_1550 * _1550) * _1547))) * min(min((_1503 * _1503) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1398) * _883, _1398 + _883, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * _944) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1319) * half(_1319)) / fast::max(_1305, 9.9999997473787516355514526367188e-05)) * half(_1338)) * half(_1338)), float3(65504.0))) * _1398), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1580, half(1.0)));
    return out;
}

