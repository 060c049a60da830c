#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct ObjectUniforms
{
    float4 positionScale;
    float4 positionOffset;
    float4 uv0ScaleOffset;
    float4 uv1ScaleOffset;
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
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
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
    float4 _36 = float4(fma(in.a_position, object.positionScale.xyz, object.positionOffset.xyz), 1.0);
    float4 _51 = float4(dot(in.a_instanceRow0, _36), dot(in.a_instanceRow1, _36), dot(in.a_instanceRow2, _36), 1.0);
    out.v_toEye = (frame.cameraPosition.xyz - _51.xyz) * 0.0625;
    float3 _84 = cross(in.a_instanceRow1.xyz, in.a_instanceRow2.xyz);
    float3 _137;
    if (dot(in.a_instanceRow0.xyz, _84) < 0.0)
    {
        _137 = -in.a_normal;
    }
    else
    {
        _137 = in.a_normal;
    }
    out.v_normal = fast::normalize(_137 * float3x3(_84, cross(in.a_instanceRow2.xyz, in.a_instanceRow0.xyz), cross(in.a_instanceRow0.xyz, in.a_instanceRow1.xyz)));
    out.gl_Position = frame.viewProjection * _51;
    return out;
}

