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
    half3 _658 = normalize(half3(in.v_normal));
    float3 _664 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _883 = max(dot(_658, half3(_664)), half(9.9999997473787516355514526367188e-05));
    float4 _922 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_883, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _941 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_922).y) - half(1.0)));
    float4 _951 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_664), _658)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _698 = half4(frame.lightDirection).xyz;
    half3 _1066 = normalize(half3(_664) + _698);
    half _1011 = clamp(dot(_658, _698), half(0.0), half(1.0));
    half4 _1135 = half4(cross(_658, _1066), half(params.facet_alpha) * clamp(dot(_658, _1066), half(0.0), half(1.0))) * half(64.0);
    half _1109 = half(4096.0) * half(params.facet_alpha);
    half _1112 = half(6.283185482025146484375) * max(mix((half(2.0) * _1011) * _883, _1011 + _883, half(params.facet_alpha)), half(0.000244140625));
    half _1114 = _1109 / (dot(_1135, _1135) * _1112);
    float3 _1193 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1196 = dot(_1193, _1193);
    float3 _1201 = _1193 * rsqrt(fast::max(_1196, 9.9999999392252902907785028219223e-09));
    float _1205 = _1196 * float(frame.punctualLights[0].positionFalloff.w);
    float _1210 = fast::clamp(fma(-_1205, _1205, 1.0), 0.0, 1.0);
    float _1229 = fast::clamp(fma(dot(-_1201, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1347 = normalize(half3(_664) + half3(_1201));
    half _1292 = clamp(dot(_658, half3(_1201)), half(0.0), half(1.0));
    half4 _1416 = half4(cross(_658, _1347), half(params.facet_alpha) * clamp(dot(_658, _1347), half(0.0), half(1.0))) * half(64.0);
    half _1393 = half(6.283185482025146484375) * max(mix((half(2.0) * _1292) * _883, _1292 + _883, half(params.facet_alpha)), half(0.000244140625));
    half _1395 = _1109 / (dot(_1416, _1416) * _1393);
    float3 _1474 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1477 = dot(_1474, _1474);
    float3 _1482 = _1474 * rsqrt(fast::max(_1477, 9.9999999392252902907785028219223e-09));
    float _1486 = _1477 * float(frame.punctualLights[1].positionFalloff.w);
    float _1491 = fast::clamp(fma(-_1486, _1486, 1.0), 0.0, 1.0);
    float _1510 = fast::clamp(fma(dot(-_1482, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1628 = normalize(half3(_664) + half3(_1482));
    half _1573 = clamp(dot(_658, half3(_1482)), half(0.0), half(1.0));
    half4 _1697 = half4(cross(_658, _1628), half(params.facet_alpha) * clamp(dot(_658, _1628), half(0.0), half(1.0))) * half(64.0);
    half _1674 = half(6.283185482025146484375) * max(mix((half(2.0) * _1573) * _883, _1573 + _883, half(params.facet_alpha)), half(0.000244140625));
    half _1676 = _1109 / (dot(_1697, _1697) * _1674);
    half3 _1719 = (fma(half4(_951).xyz, mix(half4(_922).xxx, half4(_922).yyy, half3(float3(params.facet_f0))) * _941, min(((half3(float3(params.facet_f0)) * min(_1114 * (_1114 * _1112), half(65504.0))) * _941) * (half4(frame.lightColor).xyz * _1011), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1395 * (_1395 * _1393), half(65504.0))) * _941) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1210) * half(_1210)) / fast::max(_1196, 9.9999997473787516355514526367188e-05)) * half(_1229)) * half(_1229)), float3(65504.0))) * _1292), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1676 * (_1676 * _1674), half(65504.0))) * _941) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1491) * half(_1491)) / fast::max(_1477, 9.9999997473787516355514526367188e-05)) * half(_1510)) * half(_1510)), float3(65504.0))) * _1573), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1719, half(1.0)));
    return out;
}

