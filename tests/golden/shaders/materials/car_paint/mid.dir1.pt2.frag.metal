#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
    packed_float3 facet_f0;
    float facet_alpha;
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
    half3 _670 = normalize(half3(in.v_normal));
    float3 _686 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _876 = max(dot(_670, half3(_686)), half(9.9999997473787516355514526367188e-05));
    half3 _880 = reflect(-half3(_686), _670);
    float4 _915 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_876, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _934 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_915).y) - half(1.0)));
    float4 _944 = facet_environment.sample(facet_environmentSmplr, float3(_880), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _724 = half4(frame.lightDirection).xyz;
    half3 _1051 = normalize(half3(_686) + _724);
    half _1002 = clamp(dot(_670, _724), half(0.0), half(1.0));
    half4 _1120 = half4(cross(_670, _1051), half(params.facet_alpha) * clamp(dot(_670, _1051), half(0.0), half(1.0))) * half(64.0);
    half _1094 = half(4096.0) * half(params.facet_alpha);
    half _1097 = half(6.283185482025146484375) * max(mix((half(2.0) * _1002) * _876, _1002 + _876, half(params.facet_alpha)), half(0.000244140625));
    half _1099 = _1094 / (dot(_1120, _1120) * _1097);
    float3 _1164 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1167 = dot(_1164, _1164);
    float3 _1172 = _1164 * rsqrt(fast::max(_1167, 9.9999999392252902907785028219223e-09));
    float _1176 = _1167 * float(frame.punctualLights[0].positionFalloff.w);
    float _1181 = fast::clamp(fma(-_1176, _1176, 1.0), 0.0, 1.0);
    float _1200 = fast::clamp(fma(dot(-_1172, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1310 = normalize(half3(_686) + half3(_1172));
    half _1261 = clamp(dot(_670, half3(_1172)), half(0.0), half(1.0));
    half4 _1379 = half4(cross(_670, _1310), half(params.facet_alpha) * clamp(dot(_670, _1310), half(0.0), half(1.0))) * half(64.0);
    half _1356 = half(6.283185482025146484375) * max(mix((half(2.0) * _1261) * _876, _1261 + _876, half(params.facet_alpha)), half(0.000244140625));
    half _1358 = _1094 / (dot(_1379, _1379) * _1356);
    float3 _1423 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1426 = dot(_1423, _1423);
    float3 _1431 = _1423 * rsqrt(fast::max(_1426, 9.9999999392252902907785028219223e-09));
    float _1435 = _1426 * float(frame.punctualLights[1].positionFalloff.w);
    float _1440 = fast::clamp(fma(-_1435, _1435, 1.0), 0.0, 1.0);
    float _1459 = fast::clamp(fma(dot(-_1431, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1569 = normalize(half3(_686) + half3(_1431));
    half _1520 = clamp(dot(_670, half3(_1431)), half(0.0), half(1.0));
    half4 _1638 = half4(cross(_670, _1569), half(params.facet_alpha) * clamp(dot(_670, _1569), half(0.0), half(1.0))) * half(64.0);
    half _1615 = half(6.283185482025146484375) * max(mix((half(2.0) * _1520) * _876, _1520 + _876, half(params.facet_alpha)), half(0.000244140625));
    half _1617 = _1094 / (dot(_1638, _1638) * _1615);
    half3 _1646 = (fma(half4(_944).xyz, mix(half4(_915).xxx, half4(_915).yyy, half3(float3(params.facet_f0))) * _934, min(((half3(float3(params.facet_f0)) * min(_1099 * (_1099 * _1097), half(65504.0))) * _934) * (half4(frame.lightColor).xyz * _1002), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1358 * (_1358 * _1356), half(65504.0))) * _934) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1181) * half(_1181)) / fast::max(_1167, 9.9999997473787516355514526367188e-05)) * half(_1200)) * half(_1200)), float3(65504.0))) * _1261), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1617 * (_1617 * _1615), half(65504.0))) * _934) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1440) * half(_1440)) / fast::max(_1426, 9.9999997473787516355514526367188e-05)) * half(_1459)) * half(_1459)), float3(65504.0))) * _1520), half3(float3(65504.0)));
    half _1685 = half(1.0) - _876;
    half _1688 = _1685 * _1685;
    half _1705 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1715 = facet_environment.sample(facet_environmentSmplr, float3(_880), level(_1705 * (half(4.0) * (half(2.0) - _1705))));
    half3 _1679 = mix(_1646, half4(_1715).xyz, half3(fma(half(0.959999978542327880859375), (_1688 * _1688) * _1685, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_1679, half(1.0)));
    return out;
}

