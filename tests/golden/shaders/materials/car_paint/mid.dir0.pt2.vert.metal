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
    half3 _678 = half3(out.v_normal);
    half _374 = _678.y;
    half3 _680 = half3(out.v_normal);
    half _379 = _680.z;
    half3 _682 = half3(out.v_normal);
    half _384 = _682.x;
    float3 _452 = fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * float(_374))) + (frame.sh[2].xyz * float(_379))) + (frame.sh[3].xyz * float(_384))) + (((((frame.sh[4].xyz * (float(_384) * float(_374))) + (frame.sh[5].xyz * (float(_374) * float(_379)))) + (frame.sh[6].xyz * fma(3.0 * float(_379), float(_379), -1.0))) + (frame.sh[7].xyz * (float(_384) * float(_379)))) + (frame.sh[8].xyz * fma(float(_384), float(_384), -(float(_374) * float(_374))))), float3(0.0));
    float3 _483 = float3(frame.punctualLights[0].positionFalloff.xyz) - _274;
    float _486 = dot(_483, _483);
    float3 _491 = _483 * rsqrt(fast::max(_486, 9.9999999392252902907785028219223e-09));
    float _495 = _486 * float(frame.punctualLights[0].positionFalloff.w);
    float _500 = fast::clamp(fma(-_495, _495, 1.0), 0.0, 1.0);
    float _519 = fast::clamp(fma(dot(-_491, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _561 = float3(frame.punctualLights[1].positionFalloff.xyz) - _274;
    float _564 = dot(_561, _561);
    float3 _569 = _561 * rsqrt(fast::max(_564, 9.9999999392252902907785028219223e-09));
    float _573 = _564 * float(frame.punctualLights[1].positionFalloff.w);
    float _578 = fast::clamp(fma(-_573, _573, 1.0), 0.0, 1.0);
    float _597 = fast::clamp(fma(dot(-_569, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    out.v_diffuseLight = (_452 + (fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_500 * _500) / fast::max(_486, 9.9999997473787516355514526367188e-05)) * _519) * _519), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _491), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_578 * _578) / fast::max(_564, 9.9999997473787516355514526367188e-05)) * _597) * _597), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _569), 0.0, 1.0) * 0.3183098733425140380859375));
    out.gl_Position = frame.viewProjection * _270;
    return out;
}

