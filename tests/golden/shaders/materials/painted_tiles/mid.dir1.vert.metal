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
    float2 v_uv0 [[user(locn2)]];
    float4 v_tangent [[user(locn3)]];
    float3 v_diffuseLight [[user(locn4)]];
    float3 v_directDiffuse [[user(locn5)]];
    float4 gl_Position [[position]];
};

struct main0_in
{
    float3 a_position [[attribute(0)]];
    float3 a_normal [[attribute(1)]];
    float2 a_uv0 [[attribute(2)]];
    float4 a_tangent [[attribute(5)]];
    float4 a_instanceRow0 [[attribute(6)]];
    float4 a_instanceRow1 [[attribute(7)]];
    float4 a_instanceRow2 [[attribute(8)]];
};

vertex main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant ObjectUniforms& object [[buffer(1)]])
{
    main0_out out = {};
    float4 _170 = float4(fma(in.a_position, object.positionScale.xyz, object.positionOffset.xyz), 1.0);
    float4 _185 = float4(dot(in.a_instanceRow0, _170), dot(in.a_instanceRow1, _170), dot(in.a_instanceRow2, _170), 1.0);
    out.v_toEye = (frame.cameraPosition.xyz - _185.xyz) * 0.0625;
    float3 _208 = cross(in.a_instanceRow1.xyz, in.a_instanceRow2.xyz);
    float3 _459;
    if (dot(in.a_instanceRow0.xyz, _208) < 0.0)
    {
        _459 = -in.a_normal;
    }
    else
    {
        _459 = in.a_normal;
    }
    out.v_normal = fast::normalize(_459 * float3x3(_208, cross(in.a_instanceRow2.xyz, in.a_instanceRow0.xyz), cross(in.a_instanceRow0.xyz, in.a_instanceRow1.xyz)));
    out.v_uv0 = fma(in.a_uv0, object.uv0ScaleOffset.xy, object.uv0ScaleOffset.zw);
    float3 _283 = in.a_tangent.xyz * float3x3(float3(in.a_instanceRow0.xyz), float3(in.a_instanceRow1.xyz), float3(in.a_instanceRow2.xyz));
    out.v_tangent = float4(_283 * rsqrt(fast::max(dot(_283, _283), 1.0000000031710768509710513471353e-30)), in.a_tangent.w);
    half3 _465 = half3(out.v_normal);
    half _365 = _465.y;
    half3 _467 = half3(out.v_normal);
    half _370 = _467.z;
    half3 _469 = half3(out.v_normal);
    half _375 = _469.x;
    float3 _443 = fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * float(_365))) + (frame.sh[2].xyz * float(_370))) + (frame.sh[3].xyz * float(_375))) + (((((frame.sh[4].xyz * (float(_375) * float(_365))) + (frame.sh[5].xyz * (float(_365) * float(_370)))) + (frame.sh[6].xyz * fma(3.0 * float(_370), float(_370), -1.0))) + (frame.sh[7].xyz * (float(_375) * float(_370)))) + (frame.sh[8].xyz * fma(float(_375), float(_375), -(float(_365) * float(_365))))), float3(0.0));
    out.v_directDiffuse = frame.lightColor.xyz * (fast::clamp(dot(out.v_normal, frame.lightDirection.xyz), 0.0, 1.0) * 0.3183098733425140380859375);
    out.v_diffuseLight = _443;
    out.gl_Position = frame.viewProjection * _185;
    return out;
}

