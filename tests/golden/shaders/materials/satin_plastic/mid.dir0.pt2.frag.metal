#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    packed_float3 facet_f0;
    float facet_alpha;
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
    float facet_sheenRoughness;
    float facet_sheenAlpha;
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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _744 = normalize(half3(in.v_normal));
    float3 _760 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _919 = max(dot(_744, half3(_760)), half(9.9999997473787516355514526367188e-05));
    half3 _923 = reflect(-half3(_760), _744);
    float4 _952 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_919, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _971 = facet_environment.sample(facet_environmentSmplr, float3(_923), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float4 _1003 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_919, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1863 = half4(_1003);
    half _1016 = _1863.z;
    half _1018 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _1016, half(1.0));
    half4 _1867 = half4(_1003);
    half _1023 = _1867.w;
    float4 _1032 = facet_environment.sample(facet_environmentSmplr, float3(_923), level(params.facet_sheenLod));
    float3 _1092 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1095 = dot(_1092, _1092);
    float3 _1100 = _1092 * rsqrt(fast::max(_1095, 9.9999999392252902907785028219223e-09));
    float _1104 = _1095 * float(frame.punctualLights[0].positionFalloff.w);
    float _1109 = fast::clamp(fma(-_1104, _1104, 1.0), 0.0, 1.0);
    float _1128 = fast::clamp(fma(dot(-_1100, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1139 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1109) * half(_1109)) / fast::max(_1095, 9.9999997473787516355514526367188e-05)) * half(_1128)) * half(_1128)), float3(65504.0));
    half3 _1252 = normalize(half3(_760) + half3(_1100));
    half _1194 = clamp(dot(_744, half3(_1100)), half(0.0), half(1.0));
    half _1198 = clamp(dot(_744, _1252), half(0.0), half(1.0));
    half4 _1321 = half4(cross(_744, _1252), half(params.facet_alpha) * _1198) * half(64.0);
    half _1290 = _1194 + _919;
    half _1295 = half(4096.0) * half(params.facet_alpha);
    half _1298 = half(6.283185482025146484375) * max(mix((half(2.0) * _1194) * _919, _1290, half(params.facet_alpha)), half(0.000244140625));
    half _1300 = _1295 / (dot(_1321, _1321) * _1298);
    half _1354 = half(8192.0) * fma(half(-float(_1194)), _919, _1290);
    half _1358 = half(1.0) / (half(params.facet_sheenAlpha) * _1354);
    half _1365 = half(2048.0) * half(params.facet_sheenAlpha);
    float3 _1423 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1426 = dot(_1423, _1423);
    float3 _1431 = _1423 * rsqrt(fast::max(_1426, 9.9999999392252902907785028219223e-09));
    float _1435 = _1426 * float(frame.punctualLights[1].positionFalloff.w);
    float _1440 = fast::clamp(fma(-_1435, _1435, 1.0), 0.0, 1.0);
    float _1459 = fast::clamp(fma(dot(-_1431, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1470 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1440) * half(_1440)) / fast::max(_1426, 9.9999997473787516355514526367188e-05)) * half(_1459)) * half(_1459)), float3(65504.0));
    half3 _1583 = normalize(half3(_760) + half3(_1431));
    half _1525 = clamp(dot(_744, half3(_1431)), half(0.0), half(1.0));
    half _1529 = clamp(dot(_744, _1583), half(0.0), half(1.0));
    half4 _1652 = half4(cross(_744, _1583), half(params.facet_alpha) * _1529) * half(64.0);
    half _1621 = _1525 + _919;
    half _1629 = half(6.283185482025146484375) * max(mix((half(2.0) * _1525) * _919, _1621, half(params.facet_alpha)), half(0.000244140625));
    half _1631 = _1295 / (dot(_1652, _1652) * _1629);
    half _1685 = half(8192.0) * fma(half(-float(_1525)), _919, _1621);
    half _1689 = half(1.0) / (half(params.facet_sheenAlpha) * _1685);
    half3 _1718 = (fma(half4(_1032).xyz, half3(float3(params.facet_sheenColor)) * _1016, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_971).xyz * mix(half4(_952).xxx, half4(_952).yyy, half3(float3(params.facet_f0)))) * _1018) + min(fma(half3(float3(params.facet_f0)) * min(_1300 * (_1300 * _1298), half(65504.0)), (half3(_1139) * _1194) * _1018, (half3(float3(params.facet_sheenColor)) * ((((fma(_1358, _1354, half(2.0)) * pow(max(fma(half(-float(_1198)), _1198, half(1.0)), half(0.0)), half(0.5) * (_1358 * _1354))) * half(0.15915493667125701904296875)) * (_1194 * (_1358 * _1365))) * _1023)) * half3(_1139)), half3(float3(65504.0)))) + min(fma(half3(float3(params.facet_f0)) * min(_1631 * (_1631 * _1629), half(65504.0)), (half3(_1470) * _1525) * _1018, (half3(float3(params.facet_sheenColor)) * ((((fma(_1689, _1685, half(2.0)) * pow(max(fma(half(-float(_1529)), _1529, half(1.0)), half(0.0)), half(0.5) * (_1689 * _1685))) * half(0.15915493667125701904296875)) * (_1525 * (_1689 * _1365))) * _1023)) * half3(_1470)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1718, half(1.0)));
    return out;
}

