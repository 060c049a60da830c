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
    half3 _565 = normalize(half3(in.v_normal));
    float3 _581 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _760 = max(dot(_565, half3(_581)), half(9.9999997473787516355514526367188e-05));
    float4 _799 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_760, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _818 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_799).y) - half(1.0)));
    float4 _825 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_581), _565)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _618 = half4(frame.lightDirection).xyz;
    half3 _932 = normalize(half3(_581) + _618);
    half _883 = clamp(dot(_565, _618), half(0.0), half(1.0));
    half3 _959 = cross(_565, _932);
    half _962 = clamp(dot(_565, _932), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _979 = max(mix((half(2.0) * _883) * _760, _883 + _760, half(params.facet_alpha)), half(0.000244140625));
    half _981 = half(1024.0) * half(params.facet_alpha);
    half _986 = _981 / (fma(_962, _962, dot(_959, _959)) * (half(6433.98193359375) * _979));
    float3 _1034 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1037 = dot(_1034, _1034);
    float3 _1042 = _1034 * rsqrt(fast::max(_1037, 9.9999999392252902907785028219223e-09));
    float _1046 = _1037 * float(frame.punctualLights[0].positionFalloff.w);
    float _1051 = fast::clamp(fma(-_1046, _1046, 1.0), 0.0, 1.0);
    float _1070 = fast::clamp(fma(dot(-_1042, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1180 = normalize(half3(_581) + half3(_1042));
    half _1131 = clamp(dot(_565, half3(_1042)), half(0.0), half(1.0));
    half3 _1207 = cross(_565, _1180);
    half _1210 = clamp(dot(_565, _1180), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1227 = max(mix((half(2.0) * _1131) * _760, _1131 + _760, half(params.facet_alpha)), half(0.000244140625));
    half _1234 = _981 / (fma(_1210, _1210, dot(_1207, _1207)) * (half(6433.98193359375) * _1227));
    float3 _1282 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1285 = dot(_1282, _1282);
    float3 _1290 = _1282 * rsqrt(fast::max(_1285, 9.9999999392252902907785028219223e-09));
    float _1294 = _1285 * float(frame.punctualLights[1].positionFalloff.w);
    float _1299 = fast::clamp(fma(-_1294, _1294, 1.0), 0.0, 1.0);
    float _1318 = fast::clamp(fma(dot(-_1290, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1428 = normalize(half3(_581) + half3(_1290));
    half _1379 = clamp(dot(_565, half3(_1290)), half(0.0), half(1.0));
    half3 _1455 = cross(_565, _1428);
    half _1458 = clamp(dot(_565, _1428), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1475 = max(mix((half(2.0) * _1379) * _760, _1379 + _760, half(params.facet_alpha)), half(0.000244140625));
    half _1482 = _981 / (fma(_1458, _1458, dot(_1455, _1455)) * (half(6433.98193359375) * _1475));
    half3 _1494 = (fma(half4(_825).xyz, mix(half4(_799).xxx, half4(_799).yyy, half3(float3(params.facet_f0))) * _818, min(((half3(float3(params.facet_f0)) * min(_986 * (_986 * (half(6.283185482025146484375) * _979)), half(65504.0))) * _818) * (half4(frame.lightColor).xyz * _883), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1234 * (_1234 * (half(6.283185482025146484375) * _1227)), half(65504.0))) * _818) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1051) * half(_1051)) / fast::max(_1037, 9.9999997473787516355514526367188e-05)) * half(_1070)) * half(_1070)), float3(65504.0))) * _1131), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1482 * (_1482 * (half(6.283185482025146484375) * _1475)), half(65504.0))) * _818) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1299) * half(_1299)) / fast::max(_1285, 9.9999997473787516355514526367188e-05)) * half(_1318)) * half(_1318)), float3(65504.0))) * _1379), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1494, half(1.0)));
    return out;
}

