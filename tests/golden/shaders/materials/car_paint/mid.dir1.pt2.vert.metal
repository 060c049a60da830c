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
    float4 _260 = object.model * float4(in.a_position, 1.0);
    float3 _264 = _260.xyz;
    out.v_worldPosition = _264;
    out.v_normal = fast::normalize(float3x3(object.normalMatrix[0].xyz, object.normalMatrix[1].xyz, object.normalMatrix[2].xyz) * in.a_normal);
    half3 _681 = half3(out.v_normal);
    half _377 = _681.y;
    half3 _683 = half3(out.v_normal);
    half _382 = _683.z;
    half3 _685 = half3(out.v_normal);
    half _387 = _685.x;
    float3 _455 = fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * float(_377))) + (frame.sh[2].xyz * float(_382))) + (frame.sh[3].xyz * float(_387))) + (((((frame.sh[4].xyz * (float(_387) * float(_377))) + (frame.sh[5].xyz * (float(_377) * float(_382)))) + (frame.sh[6].xyz * fma(3.0 * float(_382), float(_382), -1.0))) + (frame.sh[7].xyz * (float(_387) * float(_382)))) + (frame.sh[8].xyz * fma(float(_387), float(_387), -(float(_377) * float(_377))))), float3(0.0));
    float3 _486 = float3(frame.punctualLights[0].positionFalloff.xyz) - _264;
    float _489 = dot(_486, _486);
    float3 _494 = _486 * rsqrt(fast::max(_489, 9.9999999392252902907785028219223e-09));
    float _498 = _489 * float(frame.punctualLights[0].positionFalloff.w);
    float _503 = fast::clamp(fma(-_498, _498, 1.0), 0.0, 1.0);
    float _522 = fast::clamp(fma(dot(-_494, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _564 = float3(frame.punctualLights[1].positionFalloff.xyz) - _264;
    float _567 = dot(_564, _564);
    float3 _572 = _564 * rsqrt(fast::max(_567, 9.9999999392252902907785028219223e-09));
    float _576 = _567 * float(frame.punctualLights[1].positionFalloff.w);
    float _581 = fast::clamp(fma(-_576, _576, 1.0), 0.0, 1.0);
    float _600 = fast::clamp(fma(dot(-_572, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    out.v_diffuseLight = ((_455 + (frame.lightColor.xyz * (fast::clamp(dot(out.v_normal, frame.lightDirection.xyz), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_503 * _503) / fast::max(_489, 9.9999997473787516355514526367188e-05)) * _522) * _522), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _494), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_581 * _581) / fast::max(_567, 9.9999997473787516355514526367188e-05)) * _600) * _600), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _572), 0.0, 1.0) * 0.3183098733425140380859375));
    out.gl_Position = frame.viewProjection * _260;
    return out;
}

