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
    float3 _771;
    if (dot(in.a_instanceRow0.xyz, _298) < 0.0)
    {
        _771 = -in.a_normal;
    }
    else
    {
        _771 = in.a_normal;
    }
    out.v_normal = fast::normalize(_771 * float3x3(_298, cross(in.a_instanceRow2.xyz, in.a_instanceRow0.xyz), cross(in.a_instanceRow0.xyz, in.a_instanceRow1.xyz)));
    out.v_uv0 = fma(in.a_uv0, object.uv0ScaleOffset.xy, object.uv0ScaleOffset.zw);
    float3 _373 = in.a_tangent.xyz * float3x3(float3(in.a_instanceRow0.xyz), float3(in.a_instanceRow1.xyz), float3(in.a_instanceRow2.xyz));
    out.v_tangent = float4(_373 * rsqrt(fast::max(dot(_373, _373), 1.0000000031710768509710513471353e-30)), in.a_tangent.w);
    half3 _780 = half3(out.v_normal);
    half _475 = _780.y;
    half3 _782 = half3(out.v_normal);
    half _480 = _782.z;
    half3 _784 = half3(out.v_normal);
    half _485 = _784.x;
    float3 _553 = fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * float(_475))) + (frame.sh[2].xyz * float(_480))) + (frame.sh[3].xyz * float(_485))) + (((((frame.sh[4].xyz * (float(_485) * float(_475))) + (frame.sh[5].xyz * (float(_475) * float(_480)))) + (frame.sh[6].xyz * fma(3.0 * float(_480), float(_480), -1.0))) + (frame.sh[7].xyz * (float(_485) * float(_480)))) + (frame.sh[8].xyz * fma(float(_485), float(_485), -(float(_475) * float(_475))))), float3(0.0));
    float3 _584 = float3(frame.punctualLights[0].positionFalloff.xyz) - _285;
    float _587 = dot(_584, _584);
    float3 _592 = _584 * rsqrt(fast::max(_587, 9.9999999392252902907785028219223e-09));
    float _596 = _587 * float(frame.punctualLights[0].positionFalloff.w);
    float _601 = fast::clamp(fma(-_596, _596, 1.0), 0.0, 1.0);
    float _620 = fast::clamp(fma(dot(-_592, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _662 = float3(frame.punctualLights[1].positionFalloff.xyz) - _285;
    float _665 = dot(_662, _662);
    float3 _670 = _662 * rsqrt(fast::max(_665, 9.9999999392252902907785028219223e-09));
    float _674 = _665 * float(frame.punctualLights[1].positionFalloff.w);
    float _679 = fast::clamp(fma(-_674, _674, 1.0), 0.0, 1.0);
    float _698 = fast::clamp(fma(dot(-_670, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    out.v_diffuseLight = (_553 + (fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_601 * _601) / fast::max(_587, 9.9999997473787516355514526367188e-05)) * _620) * _620), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _592), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_679 * _679) / fast::max(_665, 9.9999997473787516355514526367188e-05)) * _698) * _698), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _670), 0.0, 1.0) * 0.3183098733425140380859375));
    out.gl_Position = frame.viewProjection * _281;
    return out;
}

