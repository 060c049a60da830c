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
    half3 _658 = normalize(half3(in.v_normal));
    float3 _664 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _862 = max(dot(_658, half3(_664)), half(9.9999997473787516355514526367188e-05));
    float4 _901 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_862, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _920 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_901).y) - half(1.0)));
    float4 _930 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_664), _658)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _975 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _978 = dot(_975, _975);
    float3 _983 = _975 * rsqrt(fast::max(_978, 9.9999999392252902907785028219223e-09));
    float _987 = _978 * float(frame.punctualLights[0].positionFalloff.w);
    float _992 = fast::clamp(fma(-_987, _987, 1.0), 0.0, 1.0);
    float _1011 = fast::clamp(fma(dot(-_983, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1129 = normalize(half3(_664) + half3(_983));
    half _1074 = clamp(dot(_658, half3(_983)), half(0.0), half(1.0));
    half4 _1198 = half4(cross(_658, _1129), half(params.facet_alpha) * clamp(dot(_658, _1129), half(0.0), half(1.0))) * half(64.0);
    half _1172 = half(4096.0) * half(params.facet_alpha);
    half _1175 = half(6.283185482025146484375) * max(mix((half(2.0) * _1074) * _862, _1074 + _862, half(params.facet_alpha)), half(0.000244140625));
    half _1177 = _1172 / (dot(_1198, _1198) * _1175);
    float3 _1256 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1259 = dot(_1256, _1256);
    float3 _1264 = _1256 * rsqrt(fast::max(_1259, 9.9999999392252902907785028219223e-09));
    float _1268 = _1259 * float(frame.punctualLights[1].positionFalloff.w);
    float _1273 = fast::clamp(fma(-_1268, _1268, 1.0), 0.0, 1.0);
    float _1292 = fast::clamp(fma(dot(-_1264, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1410 = normalize(half3(_664) + half3(_1264));
    half _1355 = clamp(dot(_658, half3(_1264)), half(0.0), half(1.0));
    half4 _1479 = half4(cross(_658, _1410), half(params.facet_alpha) * clamp(dot(_658, _1410), half(0.0), half(1.0))) * half(64.0);
    half _1456 = half(6.283185482025146484375) * max(mix((half(2.0) * _1355) * _862, _1355 + _862, half(params.facet_alpha)), half(0.000244140625));
    half _1458 = _1172 / (dot(_1479, _1479) * _1456);
    half3 _1501 = fma(half4(_930).xyz, mix(half4(_901).xxx, half4(_901).yyy, half3(float3(params.facet_f0))) * _920, min(((half3(float3(params.facet_f0)) * min(_1177 * (_1177 * _1175), half(65504.0))) * _920) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_992) * half(_992)) / fast::max(_978, 9.9999997473787516355514526367188e-05)) * half(_1011)) * half(_1011)), float3(65504.0))) * _1074), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1458 * (_1458 * _1456), half(65504.0))) * _920) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1273) * half(_1273)) / fast::max(_1259, 9.9999997473787516355514526367188e-05)) * half(_1292)) * half(_1292)), float3(65504.0))) * _1355), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1501, half(1.0)));
    return out;
}

