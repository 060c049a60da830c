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
    float4 _260 = object.model * float4(in.a_position, 1.0);
    float3 _264 = _260.xyz;
    out.v_worldPosition = _264;
    out.v_normal = fast::normalize(float3x3(object.normalMatrix[0].xyz, object.normalMatrix[1].xyz, object.normalMatrix[2].xyz) * in.a_normal);
    half3 _668 = half3(out.v_normal);
    half _364 = _668.y;
    half3 _670 = half3(out.v_normal);
    half _369 = _670.z;
    half3 _672 = half3(out.v_normal);
    half _374 = _672.x;
    float3 _442 = fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * float(_364))) + (frame.sh[2].xyz * float(_369))) + (frame.sh[3].xyz * float(_374))) + (((((frame.sh[4].xyz * (float(_374) * float(_364))) + (frame.sh[5].xyz * (float(_364) * float(_369)))) + (frame.sh[6].xyz * fma(3.0 * float(_369), float(_369), -1.0))) + (frame.sh[7].xyz * (float(_374) * float(_369)))) + (frame.sh[8].xyz * fma(float(_374), float(_374), -(float(_364) * float(_364))))), float3(0.0));
    float3 _473 = float3(frame.punctualLights[0].positionFalloff.xyz) - _264;
    float _476 = dot(_473, _473);
    float3 _481 = _473 * rsqrt(fast::max(_476, 9.9999999392252902907785028219223e-09));
    float _485 = _476 * float(frame.punctualLights[0].positionFalloff.w);
    float _490 = fast::clamp(fma(-_485, _485, 1.0), 0.0, 1.0);
    float _509 = fast::clamp(fma(dot(-_481, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _551 = float3(frame.punctualLights[1].positionFalloff.xyz) - _264;
    float _554 = dot(_551, _551);
    float3 _559 = _551 * rsqrt(fast::max(_554, 9.9999999392252902907785028219223e-09));
    float _563 = _554 * float(frame.punctualLights[1].positionFalloff.w);
    float _568 = fast::clamp(fma(-_563, _563, 1.0), 0.0, 1.0);
    float _587 = fast::clamp(fma(dot(-_559, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    out.v_diffuseLight = (_442 + (fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_490 * _490) / fast::max(_476, 9.9999997473787516355514526367188e-05)) * _509) * _509), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _481), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_568 * _568) / fast::max(_554, 9.9999997473787516355514526367188e-05)) * _587) * _587), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _559), 0.0, 1.0) * 0.3183098733425140380859375));
    out.gl_Position = frame.viewProjection * _260;
    return out;
}

