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
    half3 _727 = half3(out.v_normal);
    half _423 = _727.y;
    half3 _729 = half3(out.v_normal);
    half _428 = _729.z;
    half3 _731 = half3(out.v_normal);
    half _433 = _731.x;
    float3 _501 = fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * float(_423))) + (frame.sh[2].xyz * float(_428))) + (frame.sh[3].xyz * float(_433))) + (((((frame.sh[4].xyz * (float(_433) * float(_423))) + (frame.sh[5].xyz * (float(_423) * float(_428)))) + (frame.sh[6].xyz * fma(3.0 * float(_428), float(_428), -1.0))) + (frame.sh[7].xyz * (float(_433) * float(_428)))) + (frame.sh[8].xyz * fma(float(_433), float(_433), -(float(_423) * float(_423))))), float3(0.0));
    float3 _532 = float3(frame.punctualLights[0].positionFalloff.xyz) - _274;
    float _535 = dot(_532, _532);
    float3 _540 = _532 * rsqrt(fast::max(_535, 9.9999999392252902907785028219223e-09));
    float _544 = _535 * float(frame.punctualLights[0].positionFalloff.w);
    float _549 = fast::clamp(fma(-_544, _544, 1.0), 0.0, 1.0);
    float _568 = fast::clamp(fma(dot(-_540, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _610 = float3(frame.punctualLights[1].positionFalloff.xyz) - _274;
    float _613 = dot(_610, _610);
    float3 _618 = _610 * rsqrt(fast::max(_613, 9.9999999392252902907785028219223e-09));
    float _622 = _613 * float(frame.punctualLights[1].positionFalloff.w);
    float _627 = fast::clamp(fma(-_622, _622, 1.0), 0.0, 1.0);
    float _646 = fast::clamp(fma(dot(-_618, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    out.v_diffuseLight = ((_501 + (frame.lightColor.xyz * (fast::clamp(dot(out.v_normal, frame.lightDirection.xyz), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_549 * _549) / fast::max(_535, 9.9999997473787516355514526367188e-05)) * _568) * _568), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _540), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_627 * _627) / fast::max(_613, 9.9999997473787516355514526367188e-05)) * _646) * _646), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _618), 0.0, 1.0) * 0.3183098733425140380859375));
    out.gl_Position = frame.viewProjection * _270;
    return out;
}

