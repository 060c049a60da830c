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
    float4 _196 = object.model * float4(fma(in.a_position, object.positionScale.xyz, object.positionOffset.xyz), 1.0);
    float3 _200 = _196.xyz;
    out.v_worldPosition = _200;
    out.v_normal = fast::normalize(float3x3(object.normalMatrix[0].xyz, object.normalMatrix[1].xyz, object.normalMatrix[2].xyz) * in.a_normal);
    out.v_uv0 = fma(in.a_uv0, object.uv0ScaleOffset.xy, object.uv0ScaleOffset.zw);
    out.v_tangent = float4(float3x3(object.model[0].xyz, object.model[1].xyz, object.model[2].xyz) * in.a_tangent.xyz, in.a_tangent.w);
    float3 _378 = float3(frame.punctualLights[0].positionFalloff.xyz) - _200;
    float _381 = dot(_378, _378);
    float3 _386 = _378 * rsqrt(fast::max(_381, 9.9999999392252902907785028219223e-09));
    float _390 = _381 * float(frame.punctualLights[0].positionFalloff.w);
    float _395 = fast::clamp(fma(-_390, _390, 1.0), 0.0, 1.0);
    float _414 = fast::clamp(fma(dot(-_386, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _456 = float3(frame.punctualLights[1].positionFalloff.xyz) - _200;
    float _459 = dot(_456, _456);
    float3 _464 = _456 * rsqrt(fast::max(_459, 9.9999999392252902907785028219223e-09));
    float _468 = _459 * float(frame.punctualLights[1].positionFalloff.w);
    float _473 = fast::clamp(fma(-_468, _468, 1.0), 0.0, 1.0);
    float _492 = fast::clamp(fma(dot(-_464, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    out.v_diffuseLight = (fast::max(((frame.sh[0].xyz + (frame.sh[1].xyz * float(half3(out.v_normal).y))) + (frame.sh[2].xyz * float(half3(out.v_normal).z))) + (frame.sh[3].xyz * float(half3(out.v_normal).x)), float3(0.0)) + (fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_395 * _395) / fast::max(_381, 9.9999997473787516355514526367188e-05)) * _414) * _414), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _386), 0.0, 1.0) * 0.3183098733425140380859375))) + (fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_473 * _473) / fast::max(_459, 9.9999997473787516355514526367188e-05)) * _492) * _492), float3(65504.0)) * (fast::clamp(dot(out.v_normal, _464), 0.0, 1.0) * 0.3183098733425140380859375));
    out.gl_Position = frame.viewProjection * _196;
    return out;
}

