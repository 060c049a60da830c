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
    half3 _649 = normalize(half3(in.v_normal));
    float3 _665 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _858 = max(dot(_649, half3(_665)), half(9.9999997473787516355514526367188e-05));
    half3 _862 = reflect(-half3(_665), _649);
    float4 _897 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_858, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _916 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_897).y) - half(1.0)));
    float4 _923 = facet_environment.sample(facet_environmentSmplr, float3(_862), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _703 = half4(frame.lightDirection).xyz;
    half3 _1030 = normalize(half3(_665) + _703);
    half _981 = clamp(dot(_649, _703), half(0.0), half(1.0));
    half3 _1057 = cross(_649, _1030);
    half _1060 = clamp(dot(_649, _1030), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1077 = max(mix((half(2.0) * _981) * _858, _981 + _858, half(params.facet_alpha)), half(0.000244140625));
    half _1079 = half(1024.0) * half(params.facet_alpha);
    half _1084 = _1079 / (fma(_1060, _1060, dot(_1057, _1057)) * (half(6433.98193359375) * _1077));
    float3 _1132 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1135 = dot(_1132, _1132);
    float3 _1140 = _1132 * rsqrt(fast::max(_1135, 9.9999999392252902907785028219223e-09));
    float _1144 = _1135 * float(frame.punctualLights[0].positionFalloff.w);
    float _1149 = fast::clamp(fma(-_1144, _1144, 1.0), 0.0, 1.0);
    float _1168 = fast::clamp(fma(dot(-_1140, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1278 = normalize(half3(_665) + half3(_1140));
    half _1229 = clamp(dot(_649, half3(_1140)), half(0.0), half(1.0));
    half3 _1305 = cross(_649, _1278);
    half _1308 = clamp(dot(_649, _1278), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1325 = max(mix((half(2.0) * _1229) * _858, _1229 + _858, half(params.facet_alpha)), half(0.000244140625));
    half _1332 = _1079 / (fma(_1308, _1308, dot(_1305, _1305)) * (half(6433.98193359375) * _1325));
    float3 _1380 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1383 = dot(_1380, _1380);
    float3 _1388 = _1380 * rsqrt(fast::max(_1383, 9.9999999392252902907785028219223e-09));
    float _1392 = _1383 * float(frame.punctualLights[1].positionFalloff.w);
    float _1397 = fast::clamp(fma(-_1392, _1392, 1.0), 0.0, 1.0);
    float _1416 = fast::clamp(fma(dot(-_1388, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1526 = normalize(half3(_665) + half3(_1388));
    half _1477 = clamp(dot(_649, half3(_1388)), half(0.0), half(1.0));
    half3 _1553 = cross(_649, _1526);
    half _1556 = clamp(dot(_649, _1526), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1573 = max(mix((half(2.0) * _1477) * _858, _1477 + _858, half(params.facet_alpha)), half(0.000244140625));
    half _1580 = _1079 / (fma(_1556, _1556, dot(_1553, _1553)) * (half(6433.98193359375) * _1573));
    half3 _1592 = (fma(half4(_923).xyz, mix(half4(_897).xxx, half4(_897).yyy, half3(float3(params.facet_f0))) * _916, min(((half3(float3(params.facet_f0)) * min(_1084 * (_1084 * (half(6.283185482025146484375) * _1077)), half(65504.0))) * _916) * (half4(frame.lightColor).xyz * _981), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1332 * (_1332 * (half(6.283185482025146484375) * _1325)), half(65504.0))) * _916) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1149) * half(_1149)) / fast::max(_1135, 9.9999997473787516355514526367188e-05)) * half(_1168)) * half(_1168)), float3(65504.0))) * _1229), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1580 * (_1580 * (half(6.283185482025146484375) * _1573)), half(65504.0))) * _916) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1397) * half(_1397)) / fast::max(_1383, 9.9999997473787516355514526367188e-05)) * half(_1416)) * half(_1416)), float3(65504.0))) * _1477), half3(float3(65504.0)));
    half _1631 = half(1.0) - _858;
    half _1634 = _1631 * _1631;
    float4 _1658 = facet_environment.sample(facet_environmentSmplr, float3(_862), level(clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0)) * half(4.0)));
    out.fragColor = float4(half4(mix(_1592, half4(_1658).xyz, half3(fma(half(0.959999978542327880859375), (_1634 * _1634) * _1631, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0)))), half(1.0)));
    return out;
}

