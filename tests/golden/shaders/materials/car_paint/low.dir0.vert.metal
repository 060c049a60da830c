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
    float3 v_toEye [[user(locn0)]];
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
    float4 _100 = object.model * float4(fma(in.a_position, object.positionScale.xyz, object.positionOffset.xyz), 1.0);
    out.v_toEye = frame.cameraPosition.xyz - _100.xyz;
    out.v_normal = fast::normalize(float3x3(object.normalMatrix[0].xyz, object.normalMatrix[1].xyz, object.normalMatrix[2].xyz) * in.a_normal);
    out.v_diffuseLight = fast::max(((frame.sh[0].xyz + (frame.sh[1].xyz * float(half3(out.v_normal).y))) + (frame.sh[2].xyz * float(half3(out.v_normal).z))) + (frame.sh[3].xyz * float(half3(out.v_normal).x)), float3(0.0));
    out.gl_Position = frame.viewProjection * _100;
    return out;
}

