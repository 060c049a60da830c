#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float facet_perceptualRoughness;
    char _m3_pad[12];
    packed_float3 facet_f0;
    float facet_alpha;
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
};

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

struct main0_out
{
    float4 fragColor [[color(0)]];
};

struct main0_in
{
    float3 v_worldPosition [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _642 = normalize(half3(in.v_normal));
    float3 _648 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _865 = max(dot(_642, half3(_648)), half(9.9999997473787516355514526367188e-05));
    float4 _907 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_865, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _926 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_907).y) - half(1.0)));
    float4 _883 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_648), _642)), level(params.facet_environmentLod));
    half3 _682 = half4(frame.lightDirection).xyz;
    half _982 = clamp(dot(_642, _682), half(0.0), half(1.0));
    half3 _1040 = normalize(half3(_648) + _682);
    half4 _1109 = half4(cross(_642, _1040), half(params.facet_alpha) * clamp(dot(_642, _1040), half(0.0), half(1.0))) * half(64.0);
    half _1083 = half(4096.0) * half(params.facet_alpha);
    half _1086 = half(6.283185482025146484375) * max(mix((half(2.0) * _982) * _865, _982 + _865, half(params.facet_alpha)), half(0.000244140625));
    half _1088 = _1083 / (dot(_1109, _1109) * _1086);
    float3 _1167 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1170 = dot(_1167, _1167);
    float3 _1175 = _1167 * rsqrt(fast::max(_1170, 9.9999999392252902907785028219223e-09));
    float _1179 = _1170 * float(frame.punctualLights[0].positionFalloff.w);
    float _1184 = fast::clamp(fma(-_1179, _1179, 1.0), 0.0, 1.0);
    float _1203 = fast::clamp(fma(dot(-_1175, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1263 = clamp(dot(_642, half3(_1175)), half(0.0), half(1.0));
    half3 _1321 = normalize(half3(_648) + half3(_1175));
    half4 _1390 = half4(cross(_642, _1321), half(params.facet_alpha) * clamp(dot(_642, _1321), half(0.0), half(1.0))) * half(64.0);
    half _1367 = half(6.283185482025146484375) * max(mix((half(2.0) * _1263) * _865, _1263 + _865, half(params.facet_alpha)), half(0.000244140625));
    half _1369 = _1083 / (dot(_1390, _1390) * _1367);
    float3 _1448 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1451 = dot(_1448, _1448);
    float3 _1456 = _1448 * rsqrt(fast::max(_1451, 9.9999999392252902907785028219223e-09));
    float _1460 = _1451 * float(frame.punctualLights[1].positionFalloff.w);
    float _1465 = fast::clamp(fma(-_1460, _1460, 1.0), 0.0, 1.0);
    float _1484 = fast::clamp(fma(dot(-_1456, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1544 = clamp(dot(_642, half3(_1456)), half(0.0), half(1.0));
    half3 _1602 = normalize(half3(_648) + half3(_1456));
    half4 _1671 = half4(cross(_642, _1602), half(params.facet_alpha) * clamp(dot(_642, _1602), half(0.0), half(1.0))) * half(64.0);
    half _1648 = half(6.283185482025146484375) * max(mix((half(2.0) * _1544) * _865, _1544 + _865, half(params.facet_alpha)), half(0.000244140625));
    half _1650 = _1083 / (dot(_1671, _1671) * _1648);
    half3 _1693 = (fma(half4(_883).xyz, mix(half4(_907).xxx, half4(_907).yyy, half3(float3(params.facet_f0))) * _926, min(((half3(float3(params.facet_f0)) * min(_1088 * (_1088 * _1086), half(65504.0))) * _926) * (half4(frame.lightColor).xyz * _982), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1369 * (_1369 * _1367), half(65504.0))) * _926) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1184) * half(_1184)) / fast::max(_1170, 9.9999997473787516355514526367188e-05)) * half(_1203)) * half(_1203)), float3(65504.0))) * _1263), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1650 * (_1650 * _1648), half(65504.0))) * _926) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1465) * half(_1465)) / fast::max(_1451, 9.9999997473787516355514526367188e-05)) * half(_1484)) * half(_1484)), float3(65504.0))) * _1544), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1693, half(1.0)));
    return out;
}

