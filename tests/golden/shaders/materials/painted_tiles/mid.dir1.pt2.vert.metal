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
    float2 v_uv0 [[user(locn2)]];
    float4 v_tangent [[user(locn3)]];
    float3 v_diffuseLight [[user(locn4)]];
    float4 gl_Position [[position]];
};

struct main0_in
{
    float3 a_position [[attribute(0)]];
    float3 a_normal [[attribute(1)]];
    float2 a_uv0 [[attribute(2)]];
    float4 a_tangent [[attribute(5)]];
};

vertex main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant ObjectUniforms& object [[buffer(1)]])
{
    main0_out out = {};
    float4 _260 = object.model * float4(in.a_position, 1.0);
    float3 _264 = _260.xyz;
    out.v_worldPosition = _264;
    out.v_normal = fast::normalize(float3x3(object.normalMatrix[0].xyz, object.normalMatrix[1].xyz, object.normalMatrix[2].xyz) * in.a_normal);
    out.v_uv0 = in.a_uv0;
    out.v_tangent = float4(float3x3(object.model[0].xyz, object.model[1].xyz, object.model[2].xyz) * in.a_tangent.xyz, in.a_tangent.w);
    half3 _709 = half3(out.v_normal);
    half _405 = _709.y;
    half3 _711 = half3(out.v_normal);
    half _410 = _711.z;
    half3 _713 = half3(out.v_normal);
    half _415 = _713.x;
    float3 _483 = fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * float(_405))) + (frame.sh[2].xyz * float(_410))) + (frame.sh[3].xyz * float(_415))) + (((((frame.sh[4].xyz * (float(_415) * float(_405))) + (frame.sh[5].xyz * (float(_405) * float(_410)))) + (frame.sh[6].xyz * fma(3.0 * float(_410), float(_410), -1.0))) + (frame.sh[7].xyz * (float(_415) * float(_410)))) + (frame.sh[8].xyz * fma(float(_415), float(_415), -(float(_405) * float(_405))))), float3(0.0));
    float3 _514 = float3(frame.punctualLights[0].positionFalloff.xyz) - _264;
    float _517 = dot(_514, _514);
    float3 _522 = _514 * rsqrt(fast::max(_517, 9.9999999392252902907785028219223e-09));
    float _526 = _517 * float(frame.punctualLights[0].positionFalloff.w);
    float _531 = fast::clamp(fma(-_526, _526, 1.0), 0.0, 1.0);
    float _550 = fast::clamp(fma(dot(-_522, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _592 = float3(frame.punctualLights[1].positionFalloff.xyz) - _264;
    float _595 = dot(_592, _592);
    float3 _600 = _592 * rsqrt(fast::max(_595, 9.9999999392252902907785028219223e-09));
    float _604 = _595 * float(frame.punctualLights[1].positionFalloff.w);
    float _609 = fast::clamp(fma(-_604, _604, 1.0), 0.0, 1.0);
    float _628 = fast::clamp(fma(dot(-_600, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    out.v_diffuseLight = ((_483 + (frame.lightColor.xyz * (fast::clamp(dot(out.v_normal, frame.lightDirection.xyz), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_531 * _531) / fast::max(_517, 9.9999997473787516355514526367188e-05)) * _550) * _550), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _522), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_609 * _609) / fast::max(_595, 9.9999997473787516355514526367188e-05)) * _628) * _628), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _600), 0.0, 1.0) * 0.3183098733425140380859375));
    out.gl_Position = frame.viewProjection * _260;
    return out;
}

