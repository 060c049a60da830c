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
    half3 _637 = normalize(half3(in.v_normal));
    float3 _643 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _862 = max(dot(_637, half3(_643)), half(9.9999997473787516355514526367188e-05));
    float4 _901 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_862, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _920 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_901).y) - half(1.0)));
    float4 _927 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_643), _637)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _677 = half4(frame.lightDirection).xyz;
    half3 _1042 = normalize(half3(_643) + _677);
    half _987 = clamp(dot(_637, _677), half(0.0), half(1.0));
    half3 _1069 = cross(_637, _1042);
    half _1072 = clamp(dot(_637, _1042), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1089 = max(mix((half(2.0) * _987) * _862, _987 + _862, half(params.facet_alpha)), half(0.000244140625));
    half _1091 = half(1024.0) * half(params.facet_alpha);
    half _1096 = _1091 / (fma(_1072, _1072, dot(_1069, _1069)) * (half(6433.98193359375) * _1089));
    float3 _1158 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1161 = dot(_1158, _1158);
    float3 _1166 = _1158 * rsqrt(fast::max(_1161, 9.9999999392252902907785028219223e-09));
    float _1170 = _1161 * float(frame.punctualLights[0].positionFalloff.w);
    float _1175 = fast::clamp(fma(-_1170, _1170, 1.0), 0.0, 1.0);
    float _1194 = fast::clamp(fma(dot(-_1166, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1312 = normalize(half3(_643) + half3(_1166));
    half _1257 = clamp(dot(_637, half3(_1166)), half(0.0), half(1.0));
    half3 _1339 = cross(_637, _1312);
    half _1342 = clamp(dot(_637, _1312), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1359 = max(mix((half(2.0) * _1257) * _862, _1257 + _862, half(params.facet_alpha)), half(0.000244140625));
    half _1366 = _1091 / (fma(_1342, _1342, dot(_1339, _1339)) * (half(6433.98193359375) * _1359));
    float3 _1428 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1431 = dot(_1428, _1428);
    float3 _1436 = _1428 * rsqrt(fast::max(_1431, 9.9999999392252902907785028219223e-09));
    float _1440 = _1431 * float(frame.punctualLights[1].positionFalloff.w);
    float _1445 = fast::clamp(fma(-_1440, _1440, 1.0), 0.0, 1.0);
    float _1464 = fast::clamp(fma(dot(-_1436, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1582 = normalize(half3(_643) + half3(_1436));
    half _1527 = clamp(dot(_637, half3(_1436)), half(0.0), half(1.0));
    half3 _1609 = cross(_637, _1582);
    half _1612 = clamp(dot(_637, _1582), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1629 = max(mix((half(2.0) * _1527) * _862, _1527 + _862, half(params.facet_alpha)), half(0.000244140625));
    half _1636 = _1091 / (fma(_1612, _1612, dot(_1609, _1609)) * (half(6433.98193359375) * _1629));
    half3 _1662 = (fma(half4(_927).xyz, mix(half4(_901).xxx, half4(_901).yyy, half3(float3(params.facet_f0))) * _920, min(((half3(float3(params.facet_f0)) * min(_1096 * (_1096 * (half(6.283185482025146484375) * _1089)), half(65504.0))) * _920) * (half4(frame.lightColor).xyz * _987), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1366 * (_1366 * (half(6.283185482025146484375) * _1359)), half(65504.0))) * _920) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1175) * half(_1175)) / fast::max(_1161, 9.9999997473787516355514526367188e-05)) * half(_1194)) * half(_1194)), float3(65504.0))) * _1257), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1636 * (_1636 * (half(6.283185482025146484375) * _1629)), half(65504.0))) * _920) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1445) * half(_1445)) / fast::max(_1431, 9.9999997473787516355514526367188e-05)) * half(_1464)) * half(_1464)), float3(65504.0))) * _1527), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1662, half(1.0)));
    return out;
}

