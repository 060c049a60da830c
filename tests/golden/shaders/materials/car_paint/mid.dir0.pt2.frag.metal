#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _670 = normalize(half3(in.v_normal));
    float3 _686 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _855 = max(dot(_670, half3(_686)), half(9.9999997473787516355514526367188e-05));
    half3 _859 = reflect(-half3(_686), _670);
    float4 _894 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_855, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _913 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_894).y) - half(1.0)));
    float4 _923 = facet_environment.sample(facet_environmentSmplr, float3(_859), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _968 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _971 = dot(_968, _968);
    float3 _976 = _968 * rsqrt(fast::max(_971, 9.9999999392252902907785028219223e-09));
    float _980 = _971 * float(frame.punctualLights[0].positionFalloff.w);
    float _985 = fast::clamp(fma(-_980, _980, 1.0), 0.0, 1.0);
    float _1004 = fast::clamp(fma(dot(-_976, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1114 = normalize(half3(_686) + half3(_976));
    half _1065 = clamp(dot(_670, half3(_976)), half(0.0), half(1.0));
    half4 _1183 = half4(cross(_670, _1114), half(params.facet_alpha) * clamp(dot(_670, _1114), half(0.0), half(1.0))) * half(64.0);
    half _1157 = half(4096.0) * half(params.facet_alpha);
    half _1160 = half(6.283185482025146484375) * max(mix((half(2.0) * _1065) * _855, _1065 + _855, half(params.facet_alpha)), half(0.000244140625));
    half _1162 = _1157 / (dot(_1183, _1183) * _1160);
    float3 _1227 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1230 = dot(_1227, _1227);
    float3 _1235 = _1227 * rsqrt(fast::max(_1230, 9.9999999392252902907785028219223e-09));
    float _1239 = _1230 * float(frame.punctualLights[1].positionFalloff.w);
    float _1244 = fast::clamp(fma(-_1239, _1239, 1.0), 0.0, 1.0);
    float _1263 = fast::clamp(fma(dot(-_1235, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1373 = normalize(half3(_686) + half3(_1235));
    half _1324 = clamp(dot(_670, half3(_1235)), half(0.0), half(1.0));
    half4 _1442 = half4(cross(_670, _1373), half(params.facet_alpha) * clamp(dot(_670, _1373), half(0.0), half(1.0))) * half(64.0);
    half _1419 = half(6.283185482025146484375) * max(mix((half(2.0) * _1324) * _855, _1324 + _855, half(params.facet_alpha)), half(0.000244140625));
    half _1421 = _1157 / (dot(_1442, _1442) * _1419);
    half _1489 = half(1.0) - _855;
    half _1492 = _1489 * _1489;
    half _1509 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1519 = facet_environment.sample(facet_environmentSmplr, float3(_859), level(_1509 * (half(4.0) * (half(2.0) - _1509))));
    half3 _1483 = mix(fma(half4(_923).xyz, mix(half4(_894).xxx, half4(_894).yyy, half3(float3(params.facet_f0))) * _913, min(((half3(float3(params.facet_f0)) * min(_1162 * (_1162 * _1160), half(65504.0))) * _913) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_985) * half(_985)) / fast::max(_971, 9.9999997473787516355514526367188e-05)) * half(_1004)) * half(_1004)), float3(65504.0))) * _1065), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1421 * (_1421 * _1419), half(65504.0))) * _913) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1244) * half(_1244)) / fast::max(_1230, 9.9999997473787516355514526367188e-05)) * half(_1263)) * half(_1263)), float3(65504.0))) * _1324), half3(float3(65504.0))), half4(_1519).xyz, half3(fma(half(0.959999978542327880859375), (_1492 * _1492) * _1489, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_1483, half(1.0)));
    return out;
}

