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
    float4 _192 = float4(fma(in.a_position, object.positionScale.xyz, object.positionOffset.xyz), 1.0);
    float4 _207 = float4(dot(in.a_instanceRow0, _192), dot(in.a_instanceRow1, _192), dot(in.a_instanceRow2, _192), 1.0);
    float3 _211 = _207.xyz;
    out.v_worldPosition = _211;
    float3 _224 = cross(in.a_instanceRow1.xyz, in.a_instanceRow2.xyz);
    float3 _617;
    if (dot(in.a_instanceRow0.xyz, _224) < 0.0)
    {
        _617 = -in.a_normal;
    }
    else
    {
        _617 = in.a_normal;
    }
    out.v_normal = fast::normalize(_617 * float3x3(_224, cross(in.a_instanceRow2.xyz, in.a_instanceRow0.xyz), cross(in.a_instanceRow0.xyz, in.a_instanceRow1.xyz)));
    out.v_uv0 = fma(in.a_uv0, object.uv0ScaleOffset.xy, object.uv0ScaleOffset.zw);
    float3 _299 = in.a_tangent.xyz * float3x3(float3(in.a_instanceRow0.xyz), float3(in.a_instanceRow1.xyz), float3(in.a_instanceRow2.xyz));
    out.v_tangent = float4(_299 * rsqrt(fast::max(dot(_299, _299), 1.0000000031710768509710513471353e-30)), in.a_tangent.w);
    float3 _442 = float3(frame.punctualLights[0].positionFalloff.xyz) - _211;
    float _445 = dot(_442, _442);
    float3 _450 = _442 * rsqrt(fast::max(_445, 9.9999999392252902907785028219223e-09));
    float _454 = _445 * float(frame.punctualLights[0].positionFalloff.w);
    float _459 = fast::clamp(fma(-_454, _454, 1.0), 0.0, 1.0);
    float _478 = fast::clamp(fma(dot(-_450, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _520 = float3(frame.punctualLights[1].positionFalloff.xyz) - _211;
    float _523 = dot(_520, _520);
    float3 _528 = _520 * rsqrt(fast::max(_523, 9.9999999392252902907785028219223e-09));
    float _532 = _523 * float(frame.punctualLights[1].positionFalloff.w);
    float _537 = fast::clamp(fma(-_532, _532, 1.0), 0.0, 1.0);
    float _556 = fast::clamp(fma(dot(-_528, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    out.v_diffuseLight = (fast::max(((frame.sh[0].xyz + (frame.sh[1].xyz * float(half3(out.v_normal).y))) + (frame.sh[2].xyz * float(half3(out.v_normal).z))) + (frame.sh[3].xyz * float(half3(out.v_normal).x)), float3(0.0)) + (fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_459 * _459) / fast::max(_445, 9.9999997473787516355514526367188e-05)) * _478) * _478), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _450), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_537 * _537) / fast::max(_523, 9.9999997473787516355514526367188e-05)) * _556) * _556), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _528), 0.0, 1.0) * 0.3183098733425140380859375));
    out.gl_Position = frame.viewProjection * _207;
    return out;
}

