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
    half3 _654 = normalize(half3(in.v_normal));
    float3 _670 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _860 = max(dot(_654, half3(_670)), half(9.9999997473787516355514526367188e-05));
    half3 _864 = reflect(-half3(_670), _654);
    float4 _899 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_860, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _918 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_899).y) - half(1.0)));
    float4 _930 = facet_environment.sample(facet_environmentSmplr, float3(_864), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _708 = half4(frame.lightDirection).xyz;
    half3 _1037 = normalize(half3(_670) + _708);
    half _988 = clamp(dot(_654, _708), half(0.0), half(1.0));
    half3 _1064 = cross(_654, _1037);
    half _1067 = clamp(dot(_654, _1037), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1084 = max(mix((half(2.0) * _988) * _860, _988 + _860, half(params.facet_alpha)), half(0.000244140625));
    half _1086 = half(1024.0) * half(params.facet_alpha);
    half _1091 = _1086 / (fma(_1067, _1067, dot(_1064, _1064)) * (half(6433.98193359375) * _1084));
    float3 _1139 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1142 = dot(_1139, _1139);
    float3 _1147 = _1139 * rsqrt(fast::max(_1142, 9.9999999392252902907785028219223e-09));
    float _1151 = _1142 * float(frame.punctualLights[0].positionFalloff.w);
    float _1156 = fast::clamp(fma(-_1151, _1151, 1.0), 0.0, 1.0);
    float _1175 = fast::clamp(fma(dot(-_1147, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1285 = normalize(half3(_670) + half3(_1147));
    half _1236 = clamp(dot(_654, half3(_1147)), half(0.0), half(1.0));
    half3 _1312 = cross(_654, _1285);
    half _1315 = clamp(dot(_654, _1285), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1332 = max(mix((half(2.0) * _1236) * _860, _1236 + _860, half(params.facet_alpha)), half(0.000244140625));
    half _1339 = _1086 / (fma(_1315, _1315, dot(_1312, _1312)) * (half(6433.98193359375) * _1332));
    float3 _1387 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1390 = dot(_1387, _1387);
    float3 _1395 = _1387 * rsqrt(fast::max(_1390, 9.9999999392252902907785028219223e-09));
    float _1399 = _1390 * float(frame.punctualLights[1].positionFalloff.w);
    float _1404 = fast::clamp(fma(-_1399, _1399, 1.0), 0.0, 1.0);
    float _1423 = fast::clamp(fma(dot(-_1395, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1533 = normalize(half3(_670) + half3(_1395));
    half _1484 = clamp(dot(_654, half3(_1395)), half(0.0), half(1.0));
    half3 _1560 = cross(_654, _1533);
    half _1563 = clamp(dot(_654, _1533), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1580 = max(mix((half(2.0) * _1484) * _860, _1484 + _860, half(params.facet_alpha)), half(0.000244140625));
    half _1587 = _1086 / (fma(_1563, _1563, dot(_1560, _1560)) * (half(6433.98193359375) * _1580));
    half3 _1599 = (fma(half4(_930).xyz, mix(half4(_899).xxx, half4(_899).yyy, half3(float3(params.facet_f0))) * _918, min(((half3(float3(params.facet_f0)) * min(_1091 * (_1091 * (half(6.283185482025146484375) * _1084)), half(65504.0))) * _918) * (half4(frame.lightColor).xyz * _988), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1339 * (_1339 * (half(6.283185482025146484375) * _1332)), half(65504.0))) * _918) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1156) * half(_1156)) / fast::max(_1142, 9.9999997473787516355514526367188e-05)) * half(_1175)) * half(_1175)), float3(65504.0))) * _1236), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1587 * (_1587 * (half(6.283185482025146484375) * _1580)), half(65504.0))) * _918) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1404) * half(_1404)) / fast::max(_1390, 9.9999997473787516355514526367188e-05)) * half(_1423)) * half(_1423)), float3(65504.0))) * _1484), half3(float3(65504.0)));
    half _1638 = half(1.0) - _860;
    half _1641 = _1638 * _1638;
    half _1658 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1670 = facet_environment.sample(facet_environmentSmplr, float3(_864), level(_1658 * (half(4.0) * (half(2.0) - _1658))));
    out.fragColor = float4(half4(mix(_1599, half4(_1670).xyz, half3(fma(half(0.959999978542327880859375), (_1641 * _1641) * _1638, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0)))), half(1.0)));
    return out;
}

