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
    float4 _270 = object.model * float4(fma(in.a_position, object.positionScale.xyz, object.positionOffset.xyz), 1.0);
    float3 _274 = _270.xyz;
    out.v_worldPosition = _274;
    out.v_normal = fast::normalize(float3x3(object.normalMatrix[0].xyz, object.normalMatrix[1].xyz, object.normalMatrix[2].xyz) * in.a_normal);
    half3 _691 = half3(out.v_normal);
    half _387 = _691.y;
    half3 _693 = half3(out.v_normal);
    half _392 = _693.z;
    half3 _695 = half3(out.v_normal);
    half _397 = _695.x;
    float3 _465 = fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * float(_387))) + (frame.sh[2].xyz * float(_392))) + (frame.sh[3].xyz * float(_397))) + (((((frame.sh[4].xyz * (float(_397) * float(_387))) + (frame.sh[5].xyz * (float(_387) * float(_392)))) + (frame.sh[6].xyz * fma(3.0 * float(_392), float(_392), -1.0))) + (frame.sh[7].xyz * (float(_397) * float(_392)))) + (frame.sh[8].xyz * fma(float(_397), float(_397), -(float(_387) * float(_387))))), float3(0.0));
    float3 _496 = float3(frame.punctualLights[0].positionFalloff.xyz) - _274;
    float _499 = dot(_496, _496);
    float3 _504 = _496 * rsqrt(fast::max(_499, 9.9999999392252902907785028219223e-09));
    float _508 = _499 * float(frame.punctualLights[0].positionFalloff.w);
    float _513 = fast::clamp(fma(-_508, _508, 1.0), 0.0, 1.0);
    float _532 = fast::clamp(fma(dot(-_504, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _574 = float3(frame.punctualLights[1].positionFalloff.xyz) - _274;
    float _577 = dot(_574, _574);
    float3 _582 = _574 * rsqrt(fast::max(_577, 9.9999999392252902907785028219223e-09));
    float _586 = _577 * float(frame.punctualLights[1].positionFalloff.w);
    float _591 = fast::clamp(fma(-_586, _586, 1.0), 0.0, 1.0);
    float _610 = fast::clamp(fma(dot(-_582, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    out.v_diffuseLight = ((_465 + (frame.lightColor.xyz * (fast::clamp(dot(out.v_normal, frame.lightDirection.xyz), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_513 * _513) / fast::max(_499, 9.9999997473787516355514526367188e-05)) * _532) * _532), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _504), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_591 * _591) / fast::max(_577, 9.9999997473787516355514526367188e-05)) * _610) * _610), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _582), 0.0, 1.0) * 0.3183098733425140380859375));
    out.gl_Position = frame.viewProjection * _270;
    return out;
}

