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
    half3 _645 = normalize(half3(in.v_normal));
    float3 _661 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _833 = max(dot(_645, half3(_661)), half(9.9999997473787516355514526367188e-05));
    half3 _837 = reflect(-half3(_661), _645);
    float4 _872 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_833, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _891 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_872).y) - half(1.0)));
    float4 _898 = facet_environment.sample(facet_environmentSmplr, float3(_837), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _943 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _946 = dot(_943, _943);
    float3 _951 = _943 * rsqrt(fast::max(_946, 9.9999999392252902907785028219223e-09));
    float _955 = _946 * float(frame.punctualLights[0].positionFalloff.w);
    float _960 = fast::clamp(fma(-_955, _955, 1.0), 0.0, 1.0);
    float _979 = fast::clamp(fma(dot(-_951, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1089 = normalize(half3(_661) + half3(_951));
    half _1040 = clamp(dot(_645, half3(_951)), half(0.0), half(1.0));
    half3 _1116 = cross(_645, _1089);
    half _1119 = clamp(dot(_645, _1089), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1136 = max(mix((half(2.0) * _1040) * _833, _1040 + _833, half(params.facet_alpha)), half(0.000244140625));
    half _1138 = half(1024.0) * half(params.facet_alpha);
    half _1143 = _1138 / (fma(_1119, _1119, dot(_1116, _1116)) * (half(6433.98193359375) * _1136));
    float3 _1191 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1194 = dot(_1191, _1191);
    float3 _1199 = _1191 * rsqrt(fast::max(_1194, 9.9999999392252902907785028219223e-09));
    float _1203 = _1194 * float(frame.punctualLights[1].positionFalloff.w);
    float _1208 = fast::clamp(fma(-_1203, _1203, 1.0), 0.0, 1.0);
    float _1227 = fast::clamp(fma(dot(-_1199, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1337 = normalize(half3(_661) + half3(_1199));
    half _1288 = clamp(dot(_645, half3(_1199)), half(0.0), half(1.0));
    half3 _1364 = cross(_645, _1337);
    half _1367 = clamp(dot(_645, _1337), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1384 = max(mix((half(2.0) * _1288) * _833, _1288 + _833, half(params.facet_alpha)), half(0.000244140625));
    half _1391 = _1138 / (fma(_1367, _1367, dot(_1364, _1364)) * (half(6433.98193359375) * _1384));
    half _1440 = half(1.0) - _833;
    half _1443 = _1440 * _1440;
    float4 _1467 = facet_environment.sample(facet_environmentSmplr, float3(_837), level(clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0)) * half(4.0)));
    half3 _1434 = mix(fma(half4(_898).xyz, mix(half4(_872).xxx, half4(_872).yyy, half3(float3(params.facet_f0))) * _891, min(((half3(float3(params.facet_f0)) * min(_1143 * (_1143 * (half(6.283185482025146484375) * _1136)), half(65504.0))) * _891) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_960) * half(_960)) / fast::max(_946, 9.9999997473787516355514526367188e-05)) * half(_979)) * half(_979)), float3(65504.0))) * _1040), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1391 * (_1391 * (half(6.283185482025146484375) * _1384)), half(65504.0))) * _891) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1208) * half(_1208)) / fast::max(_1194, 9.9999997473787516355514526367188e-05)) * half(_1227)) * half(_1227)), float3(65504.0))) * _1288), half3(float3(65504.0))), half4(_1467).xyz, half3(fma(half(0.959999978542327880859375), (_1443 * _1443) * _1440, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_1434, half(1.0)));
    return out;
}

