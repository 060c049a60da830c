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
    half _915 = max(dot(_719, half3(_735)), half(9.9999997473787516355514526367188e-05));
    half3 _919 = reflect(-half3(_735), _719);
    float4 _951 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_915, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _930 = facet_environment.sample(facet_environmentSmplr, float3(_919), level(params.facet_environmentLod));
    float4 _991 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_915, half(params.facet_sheenRoughness))), level(0.0));
    half4 _2069 = half4(_991);
    half _1004 = _2069.z;
    half _1006 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _1004, half(1.0));
    half4 _2073 = half4(_991);
    half _1011 = _2073.w;
    float4 _1020 = facet_environment.sample(facet_environmentSmplr, float3(_919), level(params.facet_sheenLod));
    half3 _781 = half4(frame.lightDirection).xyz;
    half3 _793 = half4(frame.lightColor).xyz;
    half _1095 = clamp(dot(_719, _781), half(0.0), half(1.0));
    half3 _1156 = normalize(half3(_735) + _781);
    half _1102 = clamp(dot(_719, _1156), half(0.0), half(1.0));
    half _1106 = clamp(dot(_781, _1156), half(0.0), half(1.0));
    half _1186 = max(_1106 * _1106, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1216 = half4(cross(_719, _1156), half(params.facet_alpha) * _1102) * half(64.0);
    half _1196 = half(params.facet_ggxAlphaScaled) / (dot(_1216, _1216) * _1186);
    half _1249 = half(8192.0) * fma(half(-float(_1095)), _915, _1095 + _915);
    half _1253 = half(1.0) / (half(params.facet_sheenAlpha) * _1249);
    half _1260 = half(2048.0) * half(params.facet_sheenAlpha);
    float3 _1318 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1321 = dot(_1318, _1318);
    float3 _1326 = _1318 * rsqrt(fast::max(_1321, 9.9999999392252902907785028219223e-09));
    float _1330 = _1321 * float(frame.punctualLights[0].positionFalloff.w);
    float _1335 = fast::clamp(fma(-_1330, _1330, 1.0), 0.0, 1.0);
    float _1354 = fast::clamp(fma(dot(-_1326, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1365 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1335) * half(_1335)) / fast::max(_1321, 9.9999997473787516355514526367188e-05)) * half(_1354)) * half(_1354)), float3(65504.0));
    half _1417 = clamp(dot(_719, half3(_1326)), half(0.0), half(1.0));
    half3 _1478 = normalize(half3(_735) + half3(_1326));
    half _1424 = clamp(dot(_719, _1478), half(0.0), half(1.0));
    half _1428 = clamp(dot(half3(_1326), _1478), half(0.0), half(1.0));
    half _1508 = max(_1428 * _1428, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1538 = half4(cross(_719, _1478), half(params.facet_alpha) * _1424) * half(64.0);
    half _1518 = half(params.facet_ggxAlphaScaled) / (dot(_1538, _1538) * _1508);
    half _1571 = half(8192.0) * fma(half(-float(_1417)), _915, _1417 + _915);
    half _1575 = half(1.0) / (half(params.facet_sheenAlpha) * _1571);
    half3 _1604 = (fma(half4(_1020).xyz, half3(float3(params.facet_sheenColor)) * _1004, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_930).xyz * mix(half4(_951).xxx, half4(_951).yyy, half3(float3(params.facet_f0)))) * _1006) + min(fma(half3(float3(params.facet_f0)) * min((_1196 * _1196) * _1186, half(65504.0)), (_793 * _1095) * _1006, (half3(float3(params.facet_sheenColor)) * ((((fma(_1253, _1249, half(2.0)) * pow(max(fma(half(-float(_1102)), _1102, half(1.0)), half(0.0)), half(0.5) * (_1253 * _1249))) * half(0.15915493667125701904296875)) * (_1095 * (_1253 * _1260))) * _1011)) * _793), half3(float3(65504.0)))) + min(fma(half3(float3(params.facet_f0)) * min((_1518 * _1518) * _1508, half(65504.0)), (half3(_1365) * _1417) * _1006, (half3(float3(params.facet_sheenColor)) * ((((fma(_1575, _1571, half(2.0)) * pow(max(fma(half(-float(_1424)), _1424, half(1.0)), half(0.0)), half(0.5) * (_1575 * _1571))) * half(0.15915493667125701904296875)) * (_1417 * (_1575 * _1260))) * _1011)) * half3(_1365)), half3(float3(65504.0)));
    float3 _1640 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1643 = dot(_1640, _1640);
    float3 _1648 = _1640 * rsqrt(fast::max(_1643, 9.9999999392252902907785028219223e-09));
    float _1652 = _1643 * float(frame.punctualLights[1].positionFalloff.w);
    float _1657 = fast::clamp(fma(-_1652, _1652, 1.0), 0.0, 1.0);
    float _1676 = fast::clamp(fma(dot(-_1648, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1687 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1657) * half(_1657)) / fast::max(_1643, 9.9999997473787516355514526367188e-05)) * half(_1676)) * half(_1676)), float3(65504.0));
    half _1739 = clamp(dot(_719, half3(_1648)), half(0.0), half(1.0));
    half3 _1800 = normalize(half3(_735) + half3(_1648));
    half _1746 = clamp(dot(_719, _1800), half(0.0), half(1.0));
    half _1750 = clamp(dot(half3(_1648), _1800), half(0.0), half(1.0));
    half _1830 = max(_1750 * _1750, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1860 = half4(cross(_719, _1800), half(params.facet_alpha) * _1746) * half(64.0);
    half _1840 = half(params.facet_ggxAlphaScaled) / (dot(_1860, _1860) * _1830);
    half _1893 = half(8192.0) * fma(half(-float(_1739)), _915, _1739 + _915);
    half _1897 = half(1.0) / (half(params.facet_sheenAlpha) * _1893);
    out.fragColor = float4(half4(_1604 + min(fma(half3(float3(params.facet_f0)) * min((_1840 * _1840) * _1830, half(65504.0)), (half3(_1687) * _1739) * _1006, (half3(float3(params.facet_sheenColor)) * ((((fma(_1897, _1893, half(2.0)) * pow(max(fma(half(-float(_1746)), _1746, half(1.0)), half(0.0)), half(0.5) * (_1897 * _1893))) * half(0.15915493667125701904296875)) * (_1739 * (_1897 * _1260))) * _1011)) * half3(_1687)), half3(float3(65504.0))), half(1.0)));
    return out;
}

