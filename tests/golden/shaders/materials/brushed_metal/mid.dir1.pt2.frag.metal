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
    half3 _570 = normalize(half3(in.v_normal));
    float3 _586 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _765 = max(dot(_570, half3(_586)), half(9.9999997473787516355514526367188e-05));
    float4 _804 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_765, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _823 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_804).y) - half(1.0)));
    float4 _835 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_586), _570)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _623 = half4(frame.lightDirection).xyz;
    half3 _942 = normalize(half3(_586) + _623);
    half _893 = clamp(dot(_570, _623), half(0.0), half(1.0));
    half3 _969 = cross(_570, _942);
    half _972 = clamp(dot(_570, _942), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _989 = max(mix((half(2.0) * _893) * _765, _893 + _765, half(params.facet_alpha)), half(0.000244140625));
    half _991 = half(1024.0) * half(params.facet_alpha);
    half _996 = _991 / (fma(_972, _972, dot(_969, _969)) * (half(6433.98193359375) * _989));
    float3 _1044 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1047 = dot(_1044, _1044);
    float3 _1052 = _1044 * rsqrt(fast::max(_1047, 9.9999999392252902907785028219223e-09));
    float _1056 = _1047 * float(frame.punctualLights[0].positionFalloff.w);
    float _1061 = fast::clamp(fma(-_1056, _1056, 1.0), 0.0, 1.0);
    float _1080 = fast::clamp(fma(dot(-_1052, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1190 = normalize(half3(_586) + half3(_1052));
    half _1141 = clamp(dot(_570, half3(_1052)), half(0.0), half(1.0));
    half3 _1217 = cross(_570, _1190);
    half _1220 = clamp(dot(_570, _1190), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1237 = max(mix((half(2.0) * _1141) * _765, _1141 + _765, half(params.facet_alpha)), half(0.000244140625));
    half _1244 = _991 / (fma(_1220, _1220, dot(_1217, _1217)) * (half(6433.98193359375) * _1237));
    float3 _1292 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1295 = dot(_1292, _1292);
    float3 _1300 = _1292 * rsqrt(fast::max(_1295, 9.9999999392252902907785028219223e-09));
    float _1304 = _1295 * float(frame.punctualLights[1].positionFalloff.w);
    float _1309 = fast::clamp(fma(-_1304, _1304, 1.0), 0.0, 1.0);
    float _1328 = fast::clamp(fma(dot(-_1300, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1438 = normalize(half3(_586) + half3(_1300));
    half _1389 = clamp(dot(_570, half3(_1300)), half(0.0), half(1.0));
    half3 _1465 = cross(_570, _1438);
    half _1468 = clamp(dot(_570, _1438), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1485 = max(mix((half(2.0) * _1389) * _765, _1389 + _765, half(params.facet_alpha)), half(0.000244140625));
    half _1492 = _991 / (fma(_1468, _1468, dot(_1465, _1465)) * (half(6433.98193359375) * _1485));
    half3 _1504 = (fma(half4(_835).xyz, mix(half4(_804).xxx, half4(_804).yyy, half3(float3(params.facet_f0))) * _823, min(((half3(float3(params.facet_f0)) * min(_996 * (_996 * (half(6.283185482025146484375) * _989)), half(65504.0))) * _823) * (half4(frame.lightColor).xyz * _893), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1244 * (_1244 * (half(6.283185482025146484375) * _1237)), half(65504.0))) * _823) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1061) * half(_1061)) / fast::max(_1047, 9.9999997473787516355514526367188e-05)) * half(_1080)) * half(_1080)), float3(65504.0))) * _1141), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1492 * (_1492 * (half(6.283185482025146484375) * _1485)), half(65504.0))) * _823) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1309) * half(_1309)) / fast::max(_1295, 9.9999997473787516355514526367188e-05)) * half(_1328)) * half(_1328)), float3(65504.0))) * _1389), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1504, half(1.0)));
    return out;
}

