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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    float facet_anisotropy;
    float facet_anisotropicBend;
    float2 facet_anisotropicAlpha;
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
    float4 v_tangent [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _907 = normalize(half3(in.v_normal));
    float3 _913 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _1050 = half4(in.v_tangent).xyz;
    half3 _1057 = _1050 - (_907 * dot(_907, _1050));
    half _1059 = _907.z;
    half3 _2141;
    if (float(abs(_1059)) < 0.5)
    {
        _2141 = half3(-_907.y, _907.x, half(0.0));
    }
    else
    {
        _2141 = half3(half(0.0), -_1059, _907.y);
    }
    half3 _1086 = normalize(half3(select(float3(_2141), float3(_1057), bool3(float(dot(_1057, _1057)) > 0.001000000047497451305389404296875))));
    half _933 = max(dot(_907, half3(_913)), half(9.9999997473787516355514526367188e-05));
    half3 _1099 = cross(_907, _1086);
    half2 _1105 = half2(float2(1.0)) / half2(params.facet_anisotropicAlpha);
    half2 _1107 = half2(params.facet_anisotropicAlpha) * half(128.0);
    half _1113 = half(0.3183098733425140380859375) * (_1105.x * _1105.y);
    half _1129 = length(half3(_1107 * half2(dot(_1086, half3(_913)), dot(_1099, half3(_913))), half(128.0) * _933));
    half3 _2157 = select(_1099, _1086, bool3(params.facet_anisotropy >= 0.0));
    half _1363 = dot(_2157, half3(_913));
    half _1370 = fma(half(-params.facet_anisotropicBend), half(1.0) - _933, half(1.0));
    half _1373 = half(params.facet_anisotropicBend) * _1363;
    float4 _1412 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_933, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1320 = facet_environment.sample(facet_environmentSmplr, float3(((((_907 * _1370) + (_2157 * _1373)) * (half(512.0) * fma(_1370, _933, _1373 * _1363))) - (half3(_913) * (half(256.0) * fma(_1370, _1370, _1373 * _1373))))), level(params.facet_environmentLod));
    float3 _1475 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1478 = dot(_1475, _1475);
    float3 _1483 = _1475 * rsqrt(fast::max(_1478, 9.9999999392252902907785028219223e-09));
    float _1487 = _1478 * float(frame.punctualLights[0].positionFalloff.w);
    float _1492 = fast::clamp(fma(-_1487, _1487, 1.0), 0.0, 1.0);
    float _1511 = fast::clamp(fma(dot(-_1483, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1567 = clamp(dot(_907, half3(_1483)), half(0.0), half(1.0));
    float3 _1621 = fast::normalize(_913 + _1483);
    half _1574 = clamp(dot(_907, half3(_1621)), half(0.0), half(1.0));
    half2 _1639 = half2(dot(_1086, half3(_1621)), dot(_1099, half3(_1621))) * _1105;
    half _1647 = half(1.0) / fma(_1574, _1574, dot(_1639, _1639));
    half _1688 = half(1.0) - clamp(dot(half3(_1483), half3(_1621)), half(0.0), half(1.0));
    half _1691 = _1688 * _1688;
    half3 _1699 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1602 = min(((half3(float3(params.facet_f0)) + (_1699 * ((_1691 * _1691) * _1688))) * min(((_1113 * _1647) * _1647) * min(half(64.0) / fma(_1567, _1129, _933 * length(half3(_1107 * half2(dot(_1086, half3(_1483)), dot(_1099, half3(_1483))), half(128.0) * _1567))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1492) * half(_1492)) / fast::max(_1478, 9.9999997473787516355514526367188e-05)) * half(_1511)) * half(_1511)), float3(65504.0))) * _1567), half3(float3(65504.0)));
    float3 _1757 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1760 = dot(_1757, _1757);
    float3 _1765 = _1757 * rsqrt(fast::max(_1760, 9.9999999392252902907785028219223e-09));
    float _1769 = _1760 * float(frame.punctualLights[1].positionFalloff.w);
    float _1774 = fast::clamp(fma(-_1769, _1769, 1.0), 0.0, 1.0);
    float _1793 = fast::clamp(fma(dot(-_1765, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1849 = clamp(dot(_907, half3(_1765)), half(0.0), half(1.0));
    float3 _1903 = fast::normalize(_913 + _1765);
    half _1856 = clamp(dot(_907, half3(_1903)), half(0.0), half(1.0));
    half2 _1921 = half2(dot(_1086, half3(_1903)), dot(_1099, half3(_1903))) * _1105;
    half _1929 = half(1.0) / fma(_1856, _1856, dot(_1921, _1921));
    half _1970 = half(1.0) - clamp(dot(half3(_1765), half3(_1903)), half(0.0), half(1.0));
    half _1973 = _1970 * _1970;
    half3 _1884 = min(((half3(float3(params.facet_f0)) + (_1699 * ((_1973 * _1973) * _1970))) * min(((_1113 * _1929) * _1929) * min(half(64.0) / fma(_1849, _1129, _933 * length(half3(_1107 * half2(dot(_1086, half3(_1765)), dot(_1099, half3(_1765))), half(128.0) * _1849))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1774) * half(_1774)) / fast::max(_1760, 9.9999997473787516355514526367188e-05)) * half(_1793)) * half(_1793)), float3(65504.0))) * _1849), half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_1320).xyz, mix(half4(_1412).xxx, half4(_1412).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1412).y) - half(1.0)))), _1602) + _1884, half(1.0)));
    return out;
}

