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
    float3 _761;
    if (dot(in.a_instanceRow0.xyz, _298) < 0.0)
    {
        _761 = -in.a_normal;
    }
    else
    {
        _761 = in.a_normal;
    }
    out.v_normal = fast::normalize(_761 * float3x3(_298, cross(in.a_instanceRow2.xyz, in.a_instanceRow0.xyz), cross(in.a_instanceRow0.xyz, in.a_instanceRow1.xyz)));
    out.v_tangent = float4(in.a_tangent.xyz * float3x3(float3(in.a_instanceRow0.xyz), float3(in.a_instanceRow1.xyz), float3(in.a_instanceRow2.xyz)), in.a_tangent.w);
    half3 _770 = half3(out.v_normal);
    half _465 = _770.y;
    half3 _772 = half3(out.v_normal);
    half _470 = _772.z;
    half3 _774 = half3(out.v_normal);
    half _475 = _774.x;
    float3 _543 = fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * float(_465))) + (frame.sh[2].xyz * float(_470))) + (frame.sh[3].xyz * float(_475))) + (((((frame.sh[4].xyz * (float(_475) * float(_465))) + (frame.sh[5].xyz * (float(_465) * float(_470)))) + (frame.sh[6].xyz * fma(3.0 * float(_470), float(_470), -1.0))) + (frame.sh[7].xyz * (float(_475) * float(_470)))) + (frame.sh[8].xyz * fma(float(_475), float(_475), -(float(_465) * float(_465))))), float3(0.0));
    float3 _574 = float3(frame.punctualLights[0].positionFalloff.xyz) - _285;
    float _577 = dot(_574, _574);
    float3 _582 = _574 * rsqrt(fast::max(_577, 9.9999999392252902907785028219223e-09));
    float _586 = _577 * float(frame.punctualLights[0].positionFalloff.w);
    float _591 = fast::clamp(fma(-_586, _586, 1.0), 0.0, 1.0);
    float _610 = fast::clamp(fma(dot(-_582, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _652 = float3(frame.punctualLights[1].positionFalloff.xyz) - _285;
    float _655 = dot(_652, _652);
    float3 _660 = _652 * rsqrt(fast::max(_655, 9.9999999392252902907785028219223e-09));
    float _664 = _655 * float(frame.punctualLights[1].positionFalloff.w);
    float _669 = fast::clamp(fma(-_664, _664, 1.0), 0.0, 1.0);
    float _688 = fast::clamp(fma(dot(-_660, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    out.v_diffuseLight = ((_543 + (frame.lightColor.xyz * (fast::clamp(dot(out.v_normal, frame.lightDirection.xyz), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_591 * _591) / fast::max(_577, 9.9999997473787516355514526367188e-05)) * _610) * _610), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _582), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_669 * _669) / fast::max(_655, 9.9999997473787516355514526367188e-05)) * _688) * _688), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _660), 0.0, 1.0) * 0.3183098733425140380859375));
    out.gl_Position = frame.viewProjection * _281;
    return out;
}

