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
    float3 _784;
    if (dot(in.a_instanceRow0.xyz, _298) < 0.0)
    {
        _784 = -in.a_normal;
    }
    else
    {
        _784 = in.a_normal;
    }
    out.v_normal = fast::normalize(_784 * float3x3(_298, cross(in.a_instanceRow2.xyz, in.a_instanceRow0.xyz), cross(in.a_instanceRow0.xyz, in.a_instanceRow1.xyz)));
    out.v_uv0 = fma(in.a_uv0, object.uv0ScaleOffset.xy, object.uv0ScaleOffset.zw);
    float3 _373 = in.a_tangent.xyz * float3x3(float3(in.a_instanceRow0.xyz), float3(in.a_instanceRow1.xyz), float3(in.a_instanceRow2.xyz));
    out.v_tangent = float4(_373 * rsqrt(fast::max(dot(_373, _373), 1.0000000031710768509710513471353e-30)), in.a_tangent.w);
    half3 _793 = half3(out.v_normal);
    half _488 = _793.y;
    half3 _795 = half3(out.v_normal);
    half _493 = _795.z;
    half3 _797 = half3(out.v_normal);
    half _498 = _797.x;
    float3 _566 = fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * float(_488))) + (frame.sh[2].xyz * float(_493))) + (frame.sh[3].xyz * float(_498))) + (((((frame.sh[4].xyz * (float(_498) * float(_488))) + (frame.sh[5].xyz * (float(_488) * float(_493)))) + (frame.sh[6].xyz * fma(3.0 * float(_493), float(_493), -1.0))) + (frame.sh[7].xyz * (float(_498) * float(_493)))) + (frame.sh[8].xyz * fma(float(_498), float(_498), -(float(_488) * float(_488))))), float3(0.0));
    float3 _597 = float3(frame.punctualLights[0].positionFalloff.xyz) - _285;
    float _600 = dot(_597, _597);
    float3 _605 = _597 * rsqrt(fast::max(_600, 9.9999999392252902907785028219223e-09));
    float _609 = _600 * float(frame.punctualLights[0].positionFalloff.w);
    float _614 = fast::clamp(fma(-_609, _609, 1.0), 0.0, 1.0);
    float _633 = fast::clamp(fma(dot(-_605, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _675 = float3(frame.punctualLights[1].positionFalloff.xyz) - _285;
    float _678 = dot(_675, _675);
    float3 _683 = _675 * rsqrt(fast::max(_678, 9.9999999392252902907785028219223e-09));
    float _687 = _678 * float(frame.punctualLights[1].positionFalloff.w);
    float _692 = fast::clamp(fma(-_687, _687, 1.0), 0.0, 1.0);
    float _711 = fast::clamp(fma(dot(-_683, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    out.v_diffuseLight = ((_566 + (frame.lightColor.xyz * (fast::clamp(dot(out.v_normal, frame.lightDirection.xyz), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_614 * _614) / fast::max(_600, 9.9999997473787516355514526367188e-05)) * _633) * _633), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _605), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_692 * _692) / fast::max(_678, 9.9999997473787516355514526367188e-05)) * _711) * _711), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _683), 0.0, 1.0) * 0.3183098733425140380859375));
    out.gl_Position = frame.viewProjection * _281;
    return out;
}

