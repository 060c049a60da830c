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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    char _m11_pad[4];
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
    half3 _734 = normalize(half3(in.v_normal));
    float3 _750 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _909 = max(dot(_734, half3(_750)), half(9.9999997473787516355514526367188e-05));
    half3 _913 = reflect(-half3(_750), _734);
    float4 _945 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_909, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _924 = facet_environment.sample(facet_environmentSmplr, float3(_913), level(params.facet_environmentLod));
    float4 _985 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_909, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1841 = half4(_985);
    half _998 = _1841.z;
    half _1000 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _998, half(1.0));
    half4 _1845 = half4(_985);
    half _1005 = _1845.w;
    float4 _1014 = facet_environment.sample(facet_environmentSmplr, float3(_913), level(params.facet_sheenLod));
    float3 _1074 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1077 = dot(_1074, _1074);
    float3 _1082 = _1074 * rsqrt(fast::max(_1077, 9.9999999392252902907785028219223e-09));
    float _1086 = _1077 * float(frame.punctualLights[0].positionFalloff.w);
    float _1091 = fast::clamp(fma(-_1086, _1086, 1.0), 0.0, 1.0);
    float _1110 = fast::clamp(fma(dot(-_1082, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1121 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1091) * half(_1091)) / fast::max(_1077, 9.9999997473787516355514526367188e-05)) * half(_1110)) * half(_1110)), float3(65504.0));
    half _1173 = clamp(dot(_734, half3(_1082)), half(0.0), half(1.0));
    half3 _1234 = normalize(half3(_750) + half3(_1082));
    half _1180 = clamp(dot(_734, _1234), half(0.0), half(1.0));
    half _1184 = clamp(dot(half3(_1082), _1234), half(0.0), half(1.0));
    half _1266 = max(_1184 * _1184, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1289 = half4(cross(_734, _1234), half(params.facet_alpha) * _1180) * half(64.0);
    half _1300 = half(params.facet_ggxAlphaScaled) / (dot(_1289, _1289) * _1266);
    half _1336 = half(8192.0) * fma(half(-float(_1173)), _909, _1173 + _909);
    half _1340 = half(1.0) / (half(params.facet_sheenAlpha) * _1336);
    half _1347 = half(2048.0) * half(params.facet_sheenAlpha);
    float3 _1405 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1408 = dot(_1405, _1405);
    float3 _1413 = _1405 * rsqrt(fast::max(_1408, 9.9999999392252902907785028219223e-09));
    float _1417 = _1408 * float(frame.punctualLights[1].positionFalloff.w);
    float _1422 = fast::clamp(fma(-_1417, _1417, 1.0), 0.0, 1.0);
    float _1441 = fast::clamp(fma(dot(-_1413, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1452 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1422) * half(_1422)) / fast::max(_1408, 9.9999997473787516355514526367188e-05)) * half(_1441)) * half(_1441)), float3(65504.0));
    half _1504 = clamp(dot(_734, half3(_1413)), half(0.0), half(1.0));
    half3 _1565 = normalize(half3(_750) + half3(_1413));
    half _1511 = clamp(dot(_734, _1565), half(0.0), half(1.0));
    half _1515 = clamp(dot(half3(_1413), _1565), half(0.0), half(1.0));
    half _1597 = max(_1515 * _1515, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1620 = half4(cross(_734, _1565), half(params.facet_alpha) * _1511) * half(64.0);
    half _1631 = half(params.facet_ggxAlphaScaled) / (dot(_1620, _1620) * _1597);
    half _1667 = half(8192.0) * fma(half(-float(_1504)), _909, _1504 + _909);
    half _1671 = half(1.0) / (half(params.facet_sheenAlpha) * _1667);
    half3 _1700 = (fma(half4(_1014).xyz, half3(float3(params.facet_sheenColor)) * _998, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_924).xyz * mix(half4(_945).xxx, half4(_945).yyy, half3(float3(params.facet_f0)))) * _1000) + min(fma(half3(float3(params.facet_f0)) * min((_1300 * _1300) * _1266, half(65504.0)), (half3(_1121) * _1173) * _1000, (half3(float3(params.facet_sheenColor)) * ((((fma(_1340, _1336, half(2.0)) * pow(max(fma(half(-float(_1180)), _1180, half(1.0)), half(0.0)), half(0.5) * (_1340 * _1336))) * half(0.15915493667125701904296875)) * (_1173 * (_1340 * _1347))) * _1005)) * half3(_1121)), half3(float3(65504.0)))) + min(fma(half3(float3(params.facet_f0)) * min((_1631 * _1631) * _1597, half(65504.0)), (half3(_1452) * _1504) * _1000, (half3(float3(params.facet_sheenColor)) * ((((fma(_1671, _1667, half(2.0)) * pow(max(fma(half(-float(_1511)), _1511, half(1.0)), half(0.0)), half(0.5) * (_1671 * _1667))) * half(0.15915493667125701904296875)) * (_1504 * (_1671 * _1347))) * _1005)) * half3(_1452)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1700, half(1.0)));
    return out;
}

