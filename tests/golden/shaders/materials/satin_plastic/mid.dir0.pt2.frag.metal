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
    half3 _719 = normalize(half3(in.v_normal));
    float3 _735 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _894 = max(dot(_719, half3(_735)), half(9.9999997473787516355514526367188e-05));
    half3 _898 = reflect(-half3(_735), _719);
    float4 _930 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_894, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _909 = facet_environment.sample(facet_environmentSmplr, float3(_898), level(params.facet_environmentLod));
    float4 _970 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_894, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1808 = half4(_970);
    half _983 = _1808.z;
    half _985 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _983, half(1.0));
    half4 _1812 = half4(_970);
    half _990 = _1812.w;
    float4 _999 = facet_environment.sample(facet_environmentSmplr, float3(_898), level(params.facet_sheenLod));
    float3 _1059 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1062 = dot(_1059, _1059);
    float3 _1067 = _1059 * rsqrt(fast::max(_1062, 9.9999999392252902907785028219223e-09));
    float _1071 = _1062 * float(frame.punctualLights[0].positionFalloff.w);
    float _1076 = fast::clamp(fma(-_1071, _1071, 1.0), 0.0, 1.0);
    float _1095 = fast::clamp(fma(dot(-_1067, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1106 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1076) * half(_1076)) / fast::max(_1062, 9.9999997473787516355514526367188e-05)) * half(_1095)) * half(_1095)), float3(65504.0));
    half _1158 = clamp(dot(_719, half3(_1067)), half(0.0), half(1.0));
    half3 _1219 = normalize(half3(_735) + half3(_1067));
    half _1165 = clamp(dot(_719, _1219), half(0.0), half(1.0));
    half _1169 = clamp(dot(half3(_1067), _1219), half(0.0), half(1.0));
    half _1249 = max(_1169 * _1169, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1279 = half4(cross(_719, _1219), half(params.facet_alpha) * _1165) * half(64.0);
    half _1259 = half(params.facet_ggxAlphaScaled) / (dot(_1279, _1279) * _1249);
    half _1312 = half(8192.0) * fma(half(-float(_1158)), _894, _1158 + _894);
    half _1316 = half(1.0) / (half(params.facet_sheenAlpha) * _1312);
    half _1323 = half(2048.0) * half(params.facet_sheenAlpha);
    float3 _1381 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1384 = dot(_1381, _1381);
    float3 _1389 = _1381 * rsqrt(fast::max(_1384, 9.9999999392252902907785028219223e-09));
    float _1393 = _1384 * float(frame.punctualLights[1].positionFalloff.w);
    float _1398 = fast::clamp(fma(-_1393, _1393, 1.0), 0.0, 1.0);
    float _1417 = fast::clamp(fma(dot(-_1389, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1428 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1398) * half(_1398)) / fast::max(_1384, 9.9999997473787516355514526367188e-05)) * half(_1417)) * half(_1417)), float3(65504.0));
    half _1480 = clamp(dot(_719, half3(_1389)), half(0.0), half(1.0));
    half3 _1541 = normalize(half3(_735) + half3(_1389));
    half _1487 = clamp(dot(_719, _1541), half(0.0), half(1.0));
    half _1491 = clamp(dot(half3(_1389), _1541), half(0.0), half(1.0));
    half _1571 = max(_1491 * _1491, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1601 = half4(cross(_719, _1541), half(params.facet_alpha) * _1487) * half(64.0);
    half _1581 = half(params.facet_ggxAlphaScaled) / (dot(_1601, _1601) * _1571);
    half _1634 = half(8192.0) * fma(half(-float(_1480)), _894, _1480 + _894);
    half _1638 = half(1.0) / (half(params.facet_sheenAlpha) * _1634);
    half3 _1667 = (fma(half4(_999).xyz, half3(float3(params.facet_sheenColor)) * _983, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_909).xyz * mix(half4(_930).xxx, half4(_930).yyy, half3(float3(params.facet_f0)))) * _985) + min(fma(half3(float3(params.facet_f0)) * min((_1259 * _1259) * _1249, half(65504.0)), (half3(_1106) * _1158) * _985, (half3(float3(params.facet_sheenColor)) * ((((fma(_1316, _1312, half(2.0)) * pow(max(fma(half(-float(_1165)), _1165, half(1.0)), half(0.0)), half(0.5) * (_1316 * _1312))) * half(0.15915493667125701904296875)) * (_1158 * (_1316 * _1323))) * _990)) * half3(_1106)), half3(float3(65504.0)))) + min(fma(half3(float3(params.facet_f0)) * min((_1581 * _1581) * _1571, half(65504.0)), (half3(_1428) * _1480) * _985, (half3(float3(params.facet_sheenColor)) * ((((fma(_1638, _1634, half(2.0)) * pow(max(fma(half(-float(_1487)), _1487, half(1.0)), half(0.0)), half(0.5) * (_1638 * _1634))) * half(0.15915493667125701904296875)) * (_1480 * (_1638 * _1323))) * _990)) * half3(_1428)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1667, half(1.0)));
    return out;
}

