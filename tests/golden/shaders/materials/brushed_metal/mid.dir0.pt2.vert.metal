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
    float4 v_tangent [[user(locn2)]];
    float3 v_diffuseLight [[user(locn3)]];
    float4 gl_Position [[position]];
};

struct main0_in
{
    float3 a_position [[attribute(0)]];
    float3 a_normal [[attribute(1)]];
    float4 a_tangent [[attribute(5)]];
    float4 a_instanceRow0 [[attribute(6)]];
    float4 a_instanceRow1 [[attribute(7)]];
    float4 a_instanceRow2 [[attribute(8)]];
};

vertex main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant ObjectUniforms& object [[buffer(1)]])
{
    main0_out out = {};
    float4 _266 = float4(fma(in.a_position, object.positionScale.xyz, object.positionOffset.xyz), 1.0);
    float4 _281 = float4(dot(in.a_instanceRow0, _266), dot(in.a_instanceRow1, _266), dot(in.a_instanceRow2, _266), 1.0);
    float3 _285 = _281.xyz;
    out.v_worldPosition = _285;
    float3 _298 = cross(in.a_instanceRow1.xyz, in.a_instanceRow2.xyz);
    float3 _748;
    if (dot(in.a_instanceRow0.xyz, _298) < 0.0)
    {
        _748 = -in.a_normal;
    }
    else
    {
        _748 = in.a_normal;
    }
    out.v_normal = fast::normalize(_748 * float3x3(_298, cross(in.a_instanceRow2.xyz, in.a_instanceRow0.xyz), cross(in.a_instanceRow0.xyz, in.a_instanceRow1.xyz)));
    out.v_tangent = float4(in.a_tangent.xyz * float3x3(float3(in.a_instanceRow0.xyz), float3(in.a_instanceRow1.xyz), float3(in.a_instanceRow2.xyz)), in.a_tangent.w);
    half3 _757 = half3(out.v_normal);
    half _452 = _757.y;
    half3 _759 = half3(out.v_normal);
    half _457 = _759.z;
    half3 _761 = half3(out.v_normal);
    half _462 = _761.x;
    float3 _530 = fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * float(_452))) + (frame.sh[2].xyz * float(_457))) + (frame.sh[3].xyz * float(_462))) + (((((frame.sh[4].xyz * (float(_462) * float(_452))) + (frame.sh[5].xyz * (float(_452) * float(_457)))) + (frame.sh[6].xyz * fma(3.0 * float(_457), float(_457), -1.0))) + (frame.sh[7].xyz * (float(_462) * float(_457)))) + (frame.sh[8].xyz * fma(float(_462), float(_462), -(float(_452) * float(_452))))), float3(0.0));
    float3 _561 = float3(frame.punctualLights[0].positionFalloff.xyz) - _285;
    float _564 = dot(_561, _561);
    float3 _569 = _561 * rsqrt(fast::max(_564, 9.9999999392252902907785028219223e-09));
    float _573 = _564 * float(frame.punctualLights[0].positionFalloff.w);
    float _578 = fast::clamp(fma(-_573, _573, 1.0), 0.0, 1.0);
    float _597 = fast::clamp(fma(dot(-_569, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _639 = float3(frame.punctualLights[1].positionFalloff.xyz) - _285;
    float _642 = dot(_639, _639);
    float3 _647 = _639 * rsqrt(fast::max(_642, 9.9999999392252902907785028219223e-09));
    float _651 = _642 * float(frame.punctualLights[1].positionFalloff.w);
    float _656 = fast::clamp(fma(-_651, _651, 1.0), 0.0, 1.0);
    float _675 = fast::clamp(fma(dot(-_647, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    out.v_diffuseLight = (_530 + (fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_578 * _578) / fast::max(_564, 9.9999997473787516355514526367188e-05)) * _597) * _597), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _569), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_656 * _656) / fast::max(_642, 9.9999997473787516355514526367188e-05)) * _675) * _675), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _647), 0.0, 1.0) * 0.3183098733425140380859375));
    out.gl_Position = frame.viewProjection * _281;
    return out;
}

