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
    float4 a_instanceRow0 [[attribute(6)]];
    float4 a_instanceRow1 [[attribute(7)]];
    float4 a_instanceRow2 [[attribute(8)]];
};

vertex main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant ObjectUniforms& object [[buffer(1)]])
{
    main0_out out = {};
    float4 _192 = float4(fma(in.a_position, object.positionScale.xyz, object.positionOffset.xyz), 1.0);
    float4 _207 = float4(dot(in.a_instanceRow0, _192), dot(in.a_instanceRow1, _192), dot(in.a_instanceRow2, _192), 1.0);
    float3 _211 = _207.xyz;
    out.v_worldPosition = _211;
    float3 _224 = cross(in.a_instanceRow1.xyz, in.a_instanceRow2.xyz);
    float3 _579;
    if (dot(in.a_instanceRow0.xyz, _224) < 0.0)
    {
        _579 = -in.a_normal;
    }
    else
    {
        _579 = in.a_normal;
    }
    out.v_normal = fast::normalize(_579 * float3x3(_224, cross(in.a_instanceRow2.xyz, in.a_instanceRow0.xyz), cross(in.a_instanceRow0.xyz, in.a_instanceRow1.xyz)));
    float3 _404 = float3(frame.punctualLights[0].positionFalloff.xyz) - _211;
    float _407 = dot(_404, _404);
    float3 _412 = _404 * rsqrt(fast::max(_407, 9.9999999392252902907785028219223e-09));
    float _416 = _407 * float(frame.punctualLights[0].positionFalloff.w);
    float _421 = fast::clamp(fma(-_416, _416, 1.0), 0.0, 1.0);
    float _440 = fast::clamp(fma(dot(-_412, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _482 = float3(frame.punctualLights[1].positionFalloff.xyz) - _211;
    float _485 = dot(_482, _482);
    float3 _490 = _482 * rsqrt(fast::max(_485, 9.9999999392252902907785028219223e-09));
    float _494 = _485 * float(frame.punctualLights[1].positionFalloff.w);
    float _499 = fast::clamp(fma(-_494, _494, 1.0), 0.0, 1.0);
    float _518 = fast::clamp(fma(dot(-_490, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    out.v_diffuseLight = ((fast::max(((frame.sh[0].xyz + (frame.sh[1].xyz * float(half3(out.v_normal).y))) + (frame.sh[2].xyz * float(half3(out.v_normal).z))) + (frame.sh[3].xyz * float(half3(out.v_normal).x)), float3(0.0)) + (frame.lightColor.xyz * (fast::clamp(dot(out.v_normal, frame.lightDirection.xyz), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_421 * _421) / fast::max(_407, 9.9999997473787516355514526367188e-05)) * _440) * _440), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _412), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_499 * _499) / fast::max(_485, 9.9999997473787516355514526367188e-05)) * _518) * _518), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _490), 0.0, 1.0) * 0.3183098733425140380859375));
    out.gl_Position = frame.viewProjection * _207;
    return out;
}

