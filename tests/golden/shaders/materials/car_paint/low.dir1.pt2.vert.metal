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
    float4 positionScale;
    float4 positionOffset;
    float4 uv0ScaleOffset;
    float4 uv1ScaleOffset;
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
    float4 _196 = object.model * float4(fma(in.a_position, object.positionScale.xyz, object.positionOffset.xyz), 1.0);
    float3 _200 = _196.xyz;
    out.v_worldPosition = _200;
    out.v_normal = fast::normalize(float3x3(object.normalMatrix[0].xyz, object.normalMatrix[1].xyz, object.normalMatrix[2].xyz) * in.a_normal);
    float3 _354 = float3(frame.punctualLights[0].positionFalloff.xyz) - _200;
    float _357 = dot(_354, _354);
    float3 _362 = _354 * rsqrt(fast::max(_357, 9.9999999392252902907785028219223e-09));
    float _366 = _357 * float(frame.punctualLights[0].positionFalloff.w);
    float _371 = fast::clamp(fma(-_366, _366, 1.0), 0.0, 1.0);
    float _390 = fast::clamp(fma(dot(-_362, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _432 = float3(frame.punctualLights[1].positionFalloff.xyz) - _200;
    float _435 = dot(_432, _432);
    float3 _440 = _432 * rsqrt(fast::max(_435, 9.9999999392252902907785028219223e-09));
    float _444 = _435 * float(frame.punctualLights[1].positionFalloff.w);
    float _449 = fast::clamp(fma(-_444, _444, 1.0), 0.0, 1.0);
    float _468 = fast::clamp(fma(dot(-_440, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    out.v_diffuseLight = ((fast::max(((frame.sh[0].xyz + (frame.sh[1].xyz * float(half3(out.v_normal).y))) + (frame.sh[2].xyz * float(half3(out.v_normal).z))) + (frame.sh[3].xyz * float(half3(out.v_normal).x)), float3(0.0)) + (frame.lightColor.xyz * (fast::clamp(dot(out.v_normal, frame.lightDirection.xyz), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_371 * _371) / fast::max(_357, 9.9999997473787516355514526367188e-05)) * _390) * _390), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _362), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_449 * _449) / fast::max(_435, 9.9999997473787516355514526367188e-05)) * _468) * _468), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _440), 0.0, 1.0) * 0.3183098733425140380859375));
    out.gl_Position = frame.viewProjection * _196;
    return out;
}

