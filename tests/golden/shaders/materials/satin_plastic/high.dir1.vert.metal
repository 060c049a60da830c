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
    float3 v_toEye [[user(locn0)]];
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
    float4 _170 = float4(fma(in.a_position, object.positionScale.xyz, object.positionOffset.xyz), 1.0);
    float4 _185 = float4(dot(in.a_instanceRow0, _170), dot(in.a_instanceRow1, _170), dot(in.a_instanceRow2, _170), 1.0);
    out.v_toEye = frame.cameraPosition.xyz - _185.xyz;
    float3 _206 = cross(in.a_instanceRow1.xyz, in.a_instanceRow2.xyz);
    float3 _400;
    if (dot(in.a_instanceRow0.xyz, _206) < 0.0)
    {
        _400 = -in.a_normal;
    }
    else
    {
        _400 = in.a_normal;
    }
    out.v_normal = fast::normalize(_400 * float3x3(_206, cross(in.a_instanceRow2.xyz, in.a_instanceRow0.xyz), cross(in.a_instanceRow0.xyz, in.a_instanceRow1.xyz)));
    half3 _406 = half3(out.v_normal);
    half _306 = _406.y;
    half3 _408 = half3(out.v_normal);
    half _311 = _408.z;
    half3 _410 = half3(out.v_normal);
    half _316 = _410.x;
    float3 _384 = fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * float(_306))) + (frame.sh[2].xyz * float(_311))) + (frame.sh[3].xyz * float(_316))) + (((((frame.sh[4].xyz * (float(_316) * float(_306))) + (frame.sh[5].xyz * (float(_306) * float(_311)))) + (frame.sh[6].xyz * fma(3.0 * float(_311), float(_311), -1.0))) + (frame.sh[7].xyz * (float(_316) * float(_311)))) + (frame.sh[8].xyz * fma(float(_316), float(_316), -(float(_306) * float(_306))))), float3(0.0));
    out.v_diffuseLight = _384 + (frame.lightColor.xyz * (fast::clamp(dot(out.v_normal, frame.lightDirection.xyz), 0.0, 1.0) * 0.3183098733425140380859375));
    out.gl_Position = frame.viewProjection * _185;
    return out;
}

