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
    float4 _266 = float4(fma(in.a_position, object.positionScale.xyz, object.positionOffset.xyz), 1.0);
    float4 _281 = float4(dot(in.a_instanceRow0, _266), dot(in.a_instanceRow1, _266), dot(in.a_instanceRow2, _266), 1.0);
    float3 _285 = _281.xyz;
    out.v_worldPosition = _285;
    float3 _298 = cross(in.a_instanceRow1.xyz, in.a_instanceRow2.xyz);
    float3 _720;
    if (dot(in.a_instanceRow0.xyz, _298) < 0.0)
    {
        _720 = -in.a_normal;
    }
    else
    {
        _720 = in.a_normal;
    }
    out.v_normal = fast::normalize(_720 * float3x3(_298, cross(in.a_instanceRow2.xyz, in.a_instanceRow0.xyz), cross(in.a_instanceRow0.xyz, in.a_instanceRow1.xyz)));
    half3 _729 = half3(out.v_normal);
    half _424 = _729.y;
    half3 _731 = half3(out.v_normal);
    half _429 = _731.z;
    half3 _733 = half3(out.v_normal);
    half _434 = _733.x;
    float3 _502 = fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * float(_424))) + (frame.sh[2].xyz * float(_429))) + (frame.sh[3].xyz * float(_434))) + (((((frame.sh[4].xyz * (float(_434) * float(_424))) + (frame.sh[5].xyz * (float(_424) * float(_429)))) + (frame.sh[6].xyz * fma(3.0 * float(_429), float(_429), -1.0))) + (frame.sh[7].xyz * (float(_434) * float(_429)))) + (frame.sh[8].xyz * fma(float(_434), float(_434), -(float(_424) * float(_424))))), float3(0.0));
    float3 _533 = float3(frame.punctualLights[0].positionFalloff.xyz) - _285;
    float _536 = dot(_533, _533);
    float3 _541 = _533 * rsqrt(fast::max(_536, 9.9999999392252902907785028219223e-09));
    float _545 = _536 * float(frame.punctualLights[0].positionFalloff.w);
    float _550 = fast::clamp(fma(-_545, _545, 1.0), 0.0, 1.0);
    float _569 = fast::clamp(fma(dot(-_541, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _611 = float3(frame.punctualLights[1].positionFalloff.xyz) - _285;
    float _614 = dot(_611, _611);
    float3 _619 = _611 * rsqrt(fast::max(_614, 9.9999999392252902907785028219223e-09));
    float _623 = _614 * float(frame.punctualLights[1].positionFalloff.w);
    float _628 = fast::clamp(fma(-_623, _623, 1.0), 0.0, 1.0);
    float _647 = fast::clamp(fma(dot(-_619, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    out.v_diffuseLight = (_502 + (fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_550 * _550) / fast::max(_536, 9.9999997473787516355514526367188e-05)) * _569) * _569), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _541), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_628 * _628) / fast::max(_614, 9.9999997473787516355514526367188e-05)) * _647) * _647), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _619), 0.0, 1.0) * 0.3183098733425140380859375));
    out.gl_Position = frame.viewProjection * _281;
    return out;
}

