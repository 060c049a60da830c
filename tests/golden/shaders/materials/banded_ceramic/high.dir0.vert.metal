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
    float4 _170 = float4(fma(in.a_position, object.positionScale.xyz, object.positionOffset.xyz), 1.0);
    float4 _185 = float4(dot(in.a_instanceRow0, _170), dot(in.a_instanceRow1, _170), dot(in.a_instanceRow2, _170), 1.0);
    out.v_worldPosition = _185.xyz;
    float3 _202 = cross(in.a_instanceRow1.xyz, in.a_instanceRow2.xyz);
    float3 _382;
    if (dot(in.a_instanceRow0.xyz, _202) < 0.0)
    {
        _382 = -in.a_normal;
    }
    else
    {
        _382 = in.a_normal;
    }
    out.v_normal = fast::normalize(_382 * float3x3(_202, cross(in.a_instanceRow2.xyz, in.a_instanceRow0.xyz), cross(in.a_instanceRow0.xyz, in.a_instanceRow1.xyz)));
    half3 _388 = half3(out.v_normal);
    half _288 = _388.y;
    half3 _390 = half3(out.v_normal);
    half _293 = _390.z;
    half3 _392 = half3(out.v_normal);
    half _298 = _392.x;
    float3 _366 = fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * float(_288))) + (frame.sh[2].xyz * float(_293))) + (frame.sh[3].xyz * float(_298))) + (((((frame.sh[4].xyz * (float(_298) * float(_288))) + (frame.sh[5].xyz * (float(_288) * float(_293)))) + (frame.sh[6].xyz * fma(3.0 * float(_293), float(_293), -1.0))) + (frame.sh[7].xyz * (float(_298) * float(_293)))) + (frame.sh[8].xyz * fma(float(_298), float(_298), -(float(_288) * float(_288))))), float3(0.0));
    out.v_diffuseLight = _366;
    out.gl_Position = frame.viewProjection * _185;
    return out;
}

