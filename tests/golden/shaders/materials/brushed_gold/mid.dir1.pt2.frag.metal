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
    half3 _560 = normalize(half3(in.v_normal));
    float3 _576 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _750 = max(dot(_560, half3(_576)), half(9.9999997473787516355514526367188e-05));
    float4 _789 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_750, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _808 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_789).y) - half(1.0)));
    float4 _818 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_576), _560)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _613 = half4(frame.lightDirection).xyz;
    half3 _925 = normalize(half3(_576) + _613);
    half _876 = clamp(dot(_560, _613), half(0.0), half(1.0));
    half3 _952 = cross(_560, _925);
    half _955 = clamp(dot(_560, _925), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _972 = max(mix((half(2.0) * _876) * _750, _876 + _750, half(params.facet_alpha)), half(0.000244140625));
    half _974 = half(1024.0) * half(params.facet_alpha);
    half _979 = _974 / (fma(_955, _955, dot(_952, _952)) * (half(6433.98193359375) * _972));
    float3 _1027 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1030 = dot(_1027, _1027);
    float3 _1035 = _1027 * rsqrt(fast::max(_1030, 9.9999999392252902907785028219223e-09));
    float _1039 = _1030 * float(frame.punctualLights[0].positionFalloff.w);
    float _1044 = fast::clamp(fma(-_1039, _1039, 1.0), 0.0, 1.0);
    float _1063 = fast::clamp(fma(dot(-_1035, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1173 = normalize(half3(_576) + half3(_1035));
    half _1124 = clamp(dot(_560, half3(_1035)), half(0.0), half(1.0));
    half3 _1200 = cross(_560, _1173);
    half _1203 = clamp(dot(_560, _1173), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1220 = max(mix((half(2.0) * _1124) * _750, _1124 + _750, half(params.facet_alpha)), half(0.000244140625));
    half _1227 = _974 / (fma(_1203, _1203, dot(_1200, _1200)) * (half(6433.98193359375) * _1220));
    float3 _1275 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1278 = dot(_1275, _1275);
    float3 _1283 = _1275 * rsqrt(fast::max(_1278, 9.9999999392252902907785028219223e-09));
    float _1287 = _1278 * float(frame.punctualLights[1].positionFalloff.w);
    float _1292 = fast::clamp(fma(-_1287, _1287, 1.0), 0.0, 1.0);
    float _1311 = fast::clamp(fma(dot(-_1283, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1421 = normalize(half3(_576) + half3(_1283));
    half _1372 = clamp(dot(_560, half3(_1283)), half(0.0), half(1.0));
    half3 _1448 = cross(_560, _1421);
    half _1451 = clamp(dot(_560, _1421), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1468 = max(mix((half(2.0) * _1372) * _750, _1372 + _750, half(params.facet_alpha)), half(0.000244140625));
    half _1475 = _974 / (fma(_1451, _1451, dot(_1448, _1448)) * (half(6433.98193359375) * _1468));
    half3 _1487 = (fma(half4(_818).xyz, mix(half4(_789).xxx, half4(_789).yyy, half3(float3(params.facet_f0))) * _808, min(((half3(float3(params.facet_f0)) * min(_979 * (_979 * (half(6.283185482025146484375) * _972)), half(65504.0))) * _808) * (half4(frame.lightColor).xyz * _876), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1227 * (_1227 * (half(6.283185482025146484375) * _1220)), half(65504.0))) * _808) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1044) * half(_1044)) / fast::max(_1030, 9.9999997473787516355514526367188e-05)) * half(_1063)) * half(_1063)), float3(65504.0))) * _1124), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1475 * (_1475 * (half(6.283185482025146484375) * _1468)), half(65504.0))) * _808) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1292) * half(_1292)) / fast::max(_1278, 9.9999997473787516355514526367188e-05)) * half(_1311)) * half(_1311)), float3(65504.0))) * _1372), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1487, half(1.0)));
    return out;
}

