#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float anisotropy;
    float facet_pad20;
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
    half3 _568 = normalize(half3(in.v_normal));
    float3 _584 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _763 = max(dot(_568, half3(_584)), half(9.9999997473787516355514526367188e-05));
    float4 _802 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_763, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _821 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_802).y) - half(1.0)));
    float4 _831 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_584), _568)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _621 = half4(frame.lightDirection).xyz;
    half3 _938 = normalize(half3(_584) + _621);
    half _889 = clamp(dot(_568, _621), half(0.0), half(1.0));
    half3 _965 = cross(_568, _938);
    half _968 = clamp(dot(_568, _938), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _985 = max(mix((half(2.0) * _889) * _763, _889 + _763, half(params.facet_alpha)), half(0.000244140625));
    half _987 = half(1024.0) * half(params.facet_alpha);
    half _992 = _987 / (fma(_968, _968, dot(_965, _965)) * (half(6433.98193359375) * _985));
    float3 _1040 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1043 = dot(_1040, _1040);
    float3 _1048 = _1040 * rsqrt(fast::max(_1043, 9.9999999392252902907785028219223e-09));
    float _1052 = _1043 * float(frame.punctualLights[0].positionFalloff.w);
    float _1057 = fast::clamp(fma(-_1052, _1052, 1.0), 0.0, 1.0);
    float _1076 = fast::clamp(fma(dot(-_1048, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1186 = normalize(half3(_584) + half3(_1048));
    half _1137 = clamp(dot(_568, half3(_1048)), half(0.0), half(1.0));
    half3 _1213 = cross(_568, _1186);
    half _1216 = clamp(dot(_568, _1186), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1233 = max(mix((half(2.0) * _1137) * _763, _1137 + _763, half(params.facet_alpha)), half(0.000244140625));
    half _1240 = _987 / (fma(_1216, _1216, dot(_1213, _1213)) * (half(6433.98193359375) * _1233));
    float3 _1288 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1291 = dot(_1288, _1288);
    float3 _1296 = _1288 * rsqrt(fast::max(_1291, 9.9999999392252902907785028219223e-09));
    float _1300 = _1291 * float(frame.punctualLights[1].positionFalloff.w);
    float _1305 = fast::clamp(fma(-_1300, _1300, 1.0), 0.0, 1.0);
    float _1324 = fast::clamp(fma(dot(-_1296, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1434 = normalize(half3(_584) + half3(_1296));
    half _1385 = clamp(dot(_568, half3(_1296)), half(0.0), half(1.0));
    half3 _1461 = cross(_568, _1434);
    half _1464 = clamp(dot(_568, _1434), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1481 = max(mix((half(2.0) * _1385) * _763, _1385 + _763, half(params.facet_alpha)), half(0.000244140625));
    half _1488 = _987 / (fma(_1464, _1464, dot(_1461, _1461)) * (half(6433.98193359375) * _1481));
    half3 _1500 = (fma(half4(_831).xyz, mix(half4(_802).xxx, half4(_802).yyy, half3(float3(params.facet_f0))) * _821, min(((half3(float3(params.facet_f0)) * min(_992 * (_992 * (half(6.283185482025146484375) * _985)), half(65504.0))) * _821) * (half4(frame.lightColor).xyz * _889), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1240 * (_1240 * (half(6.283185482025146484375) * _1233)), half(65504.0))) * _821) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1057) * half(_1057)) / fast::max(_1043, 9.9999997473787516355514526367188e-05)) * half(_1076)) * half(_1076)), float3(65504.0))) * _1137), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1488 * (_1488 * (half(6.283185482025146484375) * _1481)), half(65504.0))) * _821) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1305) * half(_1305)) / fast::max(_1291, 9.9999997473787516355514526367188e-05)) * half(_1324)) * half(_1324)), float3(65504.0))) * _1385), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1500, half(1.0)));
    return out;
}

