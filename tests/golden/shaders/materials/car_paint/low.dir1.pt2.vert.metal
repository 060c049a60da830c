#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

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

struct ObjectUniforms
{
    float4x4 model;
    float4x4 normalMatrix;
};

struct main0_out
{
    float3 v_worldPosition [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float3 v_diffuseLight [[user(locn2)]];
    float4 gl_Position [[position]];
};

struct main0_in
{
    float3 a_position [[attribute(0)]];
    float3 a_normal [[attribute(1)]];
};

vertex main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant ObjectUniforms& object [[buffer(1)]])
{
    main0_out out = {};
    float4 _186 = object.model * float4(in.a_position, 1.0);
    float3 _190 = _186.xyz;
    out.v_worldPosition = _190;
    out.v_normal = fast::normalize(float3x3(object.normalMatrix[0].xyz, object.normalMatrix[1].xyz, object.normalMatrix[2].xyz) * in.a_normal);
    float3 _344 = float3(frame.punctualLights[0].positionFalloff.xyz) - _190;
    float _347 = dot(_344, _344);
    float3 _352 = _344 * rsqrt(fast::max(_347, 9.9999999392252902907785028219223e-09));
    float _356 = _347 * float(frame.punctualLights[0].positionFalloff.w);
    float _361 = fast::clamp(fma(-_356, _356, 1.0), 0.0, 1.0);
    float _380 = fast::clamp(fma(dot(-_352, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _422 = float3(frame.punctualLights[1].positionFalloff.xyz) - _190;
    float _425 = dot(_422, _422);
    float3 _430 = _422 * rsqrt(fast::max(_425, 9.9999999392252902907785028219223e-09));
    float _434 = _425 * float(frame.punctualLights[1].positionFalloff.w);
    float _439 = fast::clamp(fma(-_434, _434, 1.0), 0.0, 1.0);
    float _458 = fast::clamp(fma(dot(-_430, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    out.v_diffuseLight = ((fast::max(((frame.sh[0].xyz + (frame.sh[1].xyz * float(half3(out.v_normal).y))) + (frame.sh[2].xyz * float(half3(out.v_normal).z))) + (frame.sh[3].xyz * float(half3(out.v_normal).x)), float3(0.0)) + (frame.lightColor.xyz * (fast::clamp(dot(out.v_normal, frame.lightDirection.xyz), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_361 * _361) / fast::max(_347, 9.9999997473787516355514526367188e-05)) * _380) * _380), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _352), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_439 * _439) / fast::max(_425, 9.9999997473787516355514526367188e-05)) * _458) * _458), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _430), 0.0, 1.0) * 0.3183098733425140380859375));
    out.gl_Position = frame.viewProjection * _186;
    return out;
}

