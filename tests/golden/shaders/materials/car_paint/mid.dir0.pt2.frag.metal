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
    half3 _667 = normalize(half3(in.v_normal));
    float3 _683 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _852 = max(dot(_667, half3(_683)), half(9.9999997473787516355514526367188e-05));
    half3 _856 = reflect(-half3(_683), _667);
    float4 _891 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_852, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _910 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_891).y) - half(1.0)));
    float4 _917 = facet_environment.sample(facet_environmentSmplr, float3(_856), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _962 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _965 = dot(_962, _962);
    float3 _970 = _962 * rsqrt(fast::max(_965, 9.9999999392252902907785028219223e-09));
    float _974 = _965 * float(frame.punctualLights[0].positionFalloff.w);
    float _979 = fast::clamp(fma(-_974, _974, 1.0), 0.0, 1.0);
    float _998 = fast::clamp(fma(dot(-_970, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1108 = normalize(half3(_683) + half3(_970));
    half _1059 = clamp(dot(_667, half3(_970)), half(0.0), half(1.0));
    half4 _1177 = half4(cross(_667, _1108), half(params.facet_alpha) * clamp(dot(_667, _1108), half(0.0), half(1.0))) * half(64.0);
    half _1151 = half(4096.0) * half(params.facet_alpha);
    half _1154 = half(6.283185482025146484375) * max(mix((half(2.0) * _1059) * _852, _1059 + _852, half(params.facet_alpha)), half(0.000244140625));
    half _1156 = _1151 / (dot(_1177, _1177) * _1154);
    float3 _1221 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1224 = dot(_1221, _1221);
    float3 _1229 = _1221 * rsqrt(fast::max(_1224, 9.9999999392252902907785028219223e-09));
    float _1233 = _1224 * float(frame.punctualLights[1].positionFalloff.w);
    float _1238 = fast::clamp(fma(-_1233, _1233, 1.0), 0.0, 1.0);
    float _1257 = fast::clamp(fma(dot(-_1229, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1367 = normalize(half3(_683) + half3(_1229));
    half _1318 = clamp(dot(_667, half3(_1229)), half(0.0), half(1.0));
    half4 _1436 = half4(cross(_667, _1367), half(params.facet_alpha) * clamp(dot(_667, _1367), half(0.0), half(1.0))) * half(64.0);
    half _1413 = half(6.283185482025146484375) * max(mix((half(2.0) * _1318) * _852, _1318 + _852, half(params.facet_alpha)), half(0.000244140625));
    half _1415 = _1151 / (dot(_1436, _1436) * _1413);
    half _1483 = half(1.0) - _852;
    half _1486 = _1483 * _1483;
    float4 _1510 = facet_environment.sample(facet_environmentSmplr, float3(_856), level(clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0)) * half(4.0)));
    half3 _1477 = mix(fma(half4(_917).xyz, mix(half4(_891).xxx, half4(_891).yyy, half3(float3(params.facet_f0))) * _910, min(((half3(float3(params.facet_f0)) * min(_1156 * (_1156 * _1154), half(65504.0))) * _910) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_979) * half(_979)) / fast::max(_965, 9.9999997473787516355514526367188e-05)) * half(_998)) * half(_998)), float3(65504.0))) * _1059), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1415 * (_1415 * _1413), half(65504.0))) * _910) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1238) * half(_1238)) / fast::max(_1224, 9.9999997473787516355514526367188e-05)) * half(_1257)) * half(_1257)), float3(65504.0))) * _1318), half3(float3(65504.0))), half4(_1510).xyz, half3(fma(half(0.959999978542327880859375), (_1486 * _1486) * _1483, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_1477, half(1.0)));
    return out;
}

