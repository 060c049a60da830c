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
    float4 _270 = object.model * float4(fma(in.a_position, object.positionScale.xyz, object.positionOffset.xyz), 1.0);
    float3 _274 = _270.xyz;
    out.v_worldPosition = _274;
    out.v_normal = fast::normalize(float3x3(object.normalMatrix[0].xyz, object.normalMatrix[1].xyz, object.normalMatrix[2].xyz) * in.a_normal);
    out.v_uv0 = fma(in.a_uv0, object.uv0ScaleOffset.xy, object.uv0ScaleOffset.zw);
    out.v_tangent = float4(float3x3(object.model[0].xyz, object.model[1].xyz, object.model[2].xyz) * in.a_tangent.xyz, in.a_tangent.w);
    half3 _714 = half3(out.v_normal);
    half _410 = _714.y;
    half3 _716 = half3(out.v_normal);
    half _415 = _716.z;
    half3 _718 = half3(out.v_normal);
    half _420 = _718.x;
    float3 _488 = fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * float(_410))) + (frame.sh[2].xyz * float(_415))) + (frame.sh[3].xyz * float(_420))) + (((((frame.sh[4].xyz * (float(_420) * float(_410))) + (frame.sh[5].xyz * (float(_410) * float(_415)))) + (frame.sh[6].xyz * fma(3.0 * float(_415), float(_415), -1.0))) + (frame.sh[7].xyz * (float(_420) * float(_415)))) + (frame.sh[8].xyz * fma(float(_420), float(_420), -(float(_410) * float(_410))))), float3(0.0));
    float3 _519 = float3(frame.punctualLights[0].positionFalloff.xyz) - _274;
    float _522 = dot(_519, _519);
    float3 _527 = _519 * rsqrt(fast::max(_522, 9.9999999392252902907785028219223e-09));
    float _531 = _522 * float(frame.punctualLights[0].positionFalloff.w);
    float _536 = fast::clamp(fma(-_531, _531, 1.0), 0.0, 1.0);
    float _555 = fast::clamp(fma(dot(-_527, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _597 = float3(frame.punctualLights[1].positionFalloff.xyz) - _274;
    float _600 = dot(_597, _597);
    float3 _605 = _597 * rsqrt(fast::max(_600, 9.9999999392252902907785028219223e-09));
    float _609 = _600 * float(frame.punctualLights[1].positionFalloff.w);
    float _614 = fast::clamp(fma(-_609, _609, 1.0), 0.0, 1.0);
    float _633 = fast::clamp(fma(dot(-_605, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    out.v_diffuseLight = (_488 + (fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_536 * _536) / fast::max(_522, 9.9999997473787516355514526367188e-05)) * _555) * _555), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _527), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_614 * _614) / fast::max(_600, 9.9999997473787516355514526367188e-05)) * _633) * _633), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _605), 0.0, 1.0) * 0.3183098733425140380859375));
    out.gl_Position = frame.viewProjection * _270;
    return out;
}

