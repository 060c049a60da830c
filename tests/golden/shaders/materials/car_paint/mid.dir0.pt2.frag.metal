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
    float facet_clearCoat;
    float facet_clearCoatAlpha;
    float facet_clearCoatLod;
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
    half3 _660 = normalize(half3(in.v_normal));
    float3 _676 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _846 = max(dot(_660, half3(_676)), half(9.9999997473787516355514526367188e-05));
    half3 _850 = reflect(-half3(_676), _660);
    float4 _885 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_846, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _904 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_885).y) - half(1.0)));
    float4 _914 = facet_environment.sample(facet_environmentSmplr, float3(_850), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _959 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _962 = dot(_959, _959);
    float3 _967 = _959 * rsqrt(fast::max(_962, 9.9999999392252902907785028219223e-09));
    float _971 = _962 * float(frame.punctualLights[0].positionFalloff.w);
    float _976 = fast::clamp(fma(-_971, _971, 1.0), 0.0, 1.0);
    float _995 = fast::clamp(fma(dot(-_967, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1105 = normalize(half3(_676) + half3(_967));
    half _1056 = clamp(dot(_660, half3(_967)), half(0.0), half(1.0));
    half4 _1174 = half4(cross(_660, _1105), half(params.facet_alpha) * clamp(dot(_660, _1105), half(0.0), half(1.0))) * half(64.0);
    half _1148 = half(4096.0) * half(params.facet_alpha);
    half _1151 = half(6.283185482025146484375) * max(mix((half(2.0) * _1056) * _846, _1056 + _846, half(params.facet_alpha)), half(0.000244140625));
    half _1153 = _1148 / (dot(_1174, _1174) * _1151);
    float3 _1218 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1221 = dot(_1218, _1218);
    float3 _1226 = _1218 * rsqrt(fast::max(_1221, 9.9999999392252902907785028219223e-09));
    float _1230 = _1221 * float(frame.punctualLights[1].positionFalloff.w);
    float _1235 = fast::clamp(fma(-_1230, _1230, 1.0), 0.0, 1.0);
    float _1254 = fast::clamp(fma(dot(-_1226, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1364 = normalize(half3(_676) + half3(_1226));
    half _1315 = clamp(dot(_660, half3(_1226)), half(0.0), half(1.0));
    half4 _1433 = half4(cross(_660, _1364), half(params.facet_alpha) * clamp(dot(_660, _1364), half(0.0), half(1.0))) * half(64.0);
    half _1410 = half(6.283185482025146484375) * max(mix((half(2.0) * _1315) * _846, _1315 + _846, half(params.facet_alpha)), half(0.000244140625));
    half _1412 = _1148 / (dot(_1433, _1433) * _1410);
    half _1479 = half(1.0) - _846;
    half _1482 = _1479 * _1479;
    float4 _1467 = facet_environment.sample(facet_environmentSmplr, float3(_850), level(params.facet_clearCoatLod));
    half3 _1473 = mix(fma(half4(_914).xyz, mix(half4(_885).xxx, half4(_885).yyy, half3(float3(params.facet_f0))) * _904, min(((half3(float3(params.facet_f0)) * min(_1153 * (_1153 * _1151), half(65504.0))) * _904) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_976) * half(_976)) / fast::max(_962, 9.9999997473787516355514526367188e-05)) * half(_995)) * half(_995)), float3(65504.0))) * _1056), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1412 * (_1412 * _1410), half(65504.0))) * _904) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1235) * half(_1235)) / fast::max(_1221, 9.9999997473787516355514526367188e-05)) * half(_1254)) * half(_1254)), float3(65504.0))) * _1315), half3(float3(65504.0))), half4(_1467).xyz, half3(fma(half(0.959999978542327880859375), (_1482 * _1482) * _1479, half(0.039999999105930328369140625)) * half(params.facet_clearCoat)));
    out.fragColor = float4(half4(_1473, half(1.0)));
    return out;
}

