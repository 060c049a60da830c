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
    half3 _1071 = half4(in.v_tangent).xyz;
    half3 _1078 = _1071 - (_907 * dot(_907, _1071));
    half _1080 = _907.z;
    half3 _2364;
    if (float(abs(_1080)) < 0.5)
    {
        _2364 = half3(-_907.y, _907.x, half(0.0));
    }
    else
    {
        _2364 = half3(half(0.0), -_1080, _907.y);
    }
    half3 _1107 = normalize(half3(select(float3(_2364), float3(_1078), bool3(float(dot(_1078, _1078)) > 0.001000000047497451305389404296875))));
    half _933 = max(dot(_907, half3(_913)), half(9.9999997473787516355514526367188e-05));
    half3 _1120 = cross(_907, _1107);
    half2 _1126 = half2(float2(1.0)) / half2(params.facet_anisotropicAlpha);
    half2 _1128 = half2(params.facet_anisotropicAlpha) * half(128.0);
    half _1134 = half(0.3183098733425140380859375) * (_1126.x * _1126.y);
    half _1150 = length(half3(_1128 * half2(dot(_1107, half3(_913)), dot(_1120, half3(_913))), half(128.0) * _933));
    half3 _2380 = select(_1120, _1107, bool3(params.facet_anisotropy >= 0.0));
    half _1384 = dot(_2380, half3(_913));
    half _1391 = fma(half(-params.facet_anisotropicBend), half(1.0) - _933, half(1.0));
    half _1394 = half(params.facet_anisotropicBend) * _1384;
    float4 _1433 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_933, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1341 = facet_environment.sample(facet_environmentSmplr, float3(((((_907 * _1391) + (_2380 * _1394)) * (half(512.0) * fma(_1391, _933, _1394 * _1384))) - (half3(_913) * (half(256.0) * fma(_1391, _1391, _1394 * _1394))))), level(params.facet_environmentLod));
    half _1504 = clamp(dot(_907, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    float3 _1558 = fast::normalize(_913 + frame.lightDirection.xyz);
    half _1511 = clamp(dot(_907, half3(_1558)), half(0.0), half(1.0));
    half2 _1576 = half2(dot(_1107, half3(_1558)), dot(_1120, half3(_1558))) * _1126;
    half _1584 = half(1.0) / fma(_1511, _1511, dot(_1576, _1576));
    half _1625 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1558)), half(0.0), half(1.0));
    half _1628 = _1625 * _1625;
    half3 _1636 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1694 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1697 = dot(_1694, _1694);
    float3 _1702 = _1694 * rsqrt(fast::max(_1697, 9.9999999392252902907785028219223e-09));
    float _1706 = _1697 * float(frame.punctualLights[0].positionFalloff.w);
    float _1711 = fast::clamp(fma(-_1706, _1706, 1.0), 0.0, 1.0);
    float _1730 = fast::clamp(fma(dot(-_1702, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1786 = clamp(dot(_907, half3(_1702)), half(0.0), half(1.0));
    float3 _1840 = fast::normalize(_913 + _1702);
    half _1793 = clamp(dot(_907, half3(_1840)), half(0.0), half(1.0));
    half2 _1858 = half2(dot(_1107, half3(_1840)), dot(_1120, half3(_1840))) * _1126;
    half _1866 = half(1.0) / fma(_1793, _1793, dot(_1858, _1858));
    half _1907 = half(1.0) - clamp(dot(half3(_1702), half3(_1840)), half(0.0), half(1.0));
    half _1910 = _1907 * _1907;
    half3 _1821 = min(((half3(float3(params.facet_f0)) + (_1636 * ((_1910 * _1910) * _1907))) * min(((_1134 * _1866) * _1866) * min(half(64.0) / fma(_1786, _1150, _933 * length(half3(_1128 * half2(dot(_1107, half3(_1702)), dot(_1120, half3(_1702))), half(128.0) * _1786))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1711) * half(_1711)) / fast::max(_1697, 9.9999997473787516355514526367188e-05)) * half(_1730)) * half(_1730)), float3(65504.0))) * _1786), half3(float3(65504.0)));
    half3 _1940 = fma(half4(_1341).xyz, mix(half4(_1433).xxx, half4(_1433).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1433).y) - half(1.0)))), min(((half3(float3(params.facet_f0)) + (_1636 * ((_1628 * _1628) * _1625))) * min(((_1134 * _1584) * _1584) * min(half(64.0) / fma(_1504, _1150, _933 * length(half3(_1128 * half2(dot(_1107, half3(frame.lightDirection.xyz)), dot(_1120, half3(frame.lightDirection.xyz))), half(128.0) * _1504))), half(65504.0)), half(65504.0))) * (half4(frame.lightColor).xyz * _1504), half3(float3(65504.0)))) + _1821;
    float3 _1976 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1979 = dot(_1976, _1976);
    float3 _1984 = _1976 * rsqrt(fast::max(_1979, 9.9999999392252902907785028219223e-09));
    float _1988 = _1979 * float(frame.punctualLights[1].positionFalloff.w);
    float _1993 = fast::clamp(fma(-_1988, _1988, 1.0), 0.0, 1.0);
    float _2012 = fast::clamp(fma(dot(-_1984, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _2068 = clamp(dot(_907, half3(_1984)), half(0.0), half(1.0));
    float3 _2122 = fast::normalize(_913 + _1984);
    half _2075 = clamp(dot(_907, half3(_2122)), half(0.0), half(1.0));
    half2 _2140 = half2(dot(_1107, half3(_2122)), dot(_1120, half3(_2122))) * _1126;
    half _2148 = half(1.0) / fma(_2075, _2075, dot(_2140, _2140));
    half _2189 = half(1.0) - clamp(dot(half3(_1984), half3(_2122)), half(0.0), half(1.0));
    half _2192 = _2189 * _2189;
    half3 _2103 = min(((half3(float3(params.facet_f0)) + (_1636 * ((_2192 * _2192) * _2189))) * min(((_1134 * _2148) * _2148) * min(half(64.0) / fma(_2068, _1150, _933 * length(half3(_1128 * half2(dot(_1107, half3(_1984)), dot(_1120, half3(_1984))), half(128.0) * _2068))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1993) * half(_1993)) / fast::max(_1979, 9.9999997473787516355514526367188e-05)) * half(_2012)) * half(_2012)), float3(65504.0))) * _2068), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1940 + _2103, half(1.0)));
    return out;
}

