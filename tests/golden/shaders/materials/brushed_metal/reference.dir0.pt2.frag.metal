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
    float3 _899 = fast::normalize(in.v_normal);
    float3 _905 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float3 _1049 = in.v_tangent.xyz - (_899 * dot(_899, in.v_tangent.xyz));
    float _1051 = _899.z;
    float3 _2117;
    if (abs(_1051) < 0.5)
    {
        _2117 = float3(-_899.y, _899.x, 0.0);
    }
    else
    {
        _2117 = float3(0.0, -_1051, _899.y);
    }
    float3 _1078 = fast::normalize(select(_2117, _1049, bool3(dot(_1049, _1049) > 0.001000000047497451305389404296875)));
    float _925 = fast::max(dot(_899, _905), 9.9999997473787516355514526367188e-05);
    float3 _1091 = cross(_899, _1078);
    float2 _1097 = float2(1.0) / params.facet_anisotropicAlpha;
    float2 _1099 = params.facet_anisotropicAlpha * 128.0;
    float _1105 = 0.3183098733425140380859375 * (_1097.x * _1097.y);
    float _1121 = length(float3(_1099 * float2(dot(_1078, _905), dot(_1091, _905)), 128.0 * _925));
    float3 _2133 = select(_1091, _1078, bool3(params.facet_anisotropy >= 0.0));
    float _1355 = dot(_2133, _905);
    float _1362 = fma(-params.facet_anisotropicBend, 1.0 - _925, 1.0);
    float _1365 = params.facet_anisotropicBend * _1355;
    float4 _1404 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_925, params.facet_perceptualRoughness), level(0.0));
    float3 _1466 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1469 = dot(_1466, _1466);
    float3 _1474 = _1466 * rsqrt(fast::max(_1469, 9.9999999392252902907785028219223e-09));
    float _1478 = _1469 * float(frame.punctualLights[0].positionFalloff.w);
    float _1483 = fast::clamp(fma(-_1478, _1478, 1.0), 0.0, 1.0);
    float _1502 = fast::clamp(fma(dot(-_1474, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1555 = fast::clamp(dot(_899, _1474), 0.0, 1.0);
    float3 _1608 = fast::normalize(_905 + _1474);
    float _1562 = fast::clamp(dot(_899, _1608), 0.0, 1.0);
    float2 _1625 = float2(dot(_1078, _1608), dot(_1091, _1608)) * _1097;
    float _1633 = 1.0 / fma(_1562, _1562, dot(_1625, _1625));
    float _1672 = 1.0 - fast::clamp(dot(_1474, _1608), 0.0, 1.0);
    float _1675 = _1672 * _1672;
    float3 _1683 = float3(1.0) - float3(params.facet_f0);
    float3 _1740 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1743 = dot(_1740, _1740);
    float3 _1748 = _1740 * rsqrt(fast::max(_1743, 9.9999999392252902907785028219223e-09));
    float _1752 = _1743 * float(frame.punctualLights[1].positionFalloff.w);
    float _1757 = fast::clamp(fma(-_1752, _1752, 1.0), 0.0, 1.0);
    float _1776 = fast::clamp(fma(dot(-_1748, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1829 = fast::clamp(dot(_899, _1748), 0.0, 1.0);
    float3 _1882 = fast::normalize(_905 + _1748);
    float _1836 = fast::clamp(dot(_899, _1882), 0.0, 1.0);
    float2 _1899 = float2(dot(_1078, _1882), dot(_1091, _1882)) * _1097;
    float _1907 = 1.0 / fma(_1836, _1836, dot(_1899, _1899));
    float _1946 = 1.0 - fast::clamp(dot(_1748, _1882), 0.0, 1.0);
    float _1949 = _1946 * _1946;
    float3 _1979 = fma(facet_environment.sample(facet_environmentSmplr, ((((_899 * _1362) + (_2133 * _1365)) * (512.0 * fma(_1362, _925, _1365 * _1355))) - (_905 * (256.0 * fma(_1362, _1362, _1365 * _1365)))), level(params.facet_environmentLod)).xyz, mix(_1404.xxx, _1404.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1404.y) - 1.0))), fast::min(((float3(params.facet_f0) + (_1683 * ((_1675 * _1675) * _1672))) * (((_1105 * _1633) * _1633) * (64.0 / fma(_1555, _1121, _925 * length(float3(_1099 * float2(dot(_1078, _1474), dot(_1091, _1474)), 128.0 * _1555)))))) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1483 * _1483) / fast::max(_1469, 9.9999997473787516355514526367188e-05)) * _1502) * _1502)) * _1555), float3(65504.0))) + fast::min(((float3(params.facet_f0) + (_1683 * ((_1949 * _1949) * _1946))) * (((_1105 * _1907) * _1907) * (64.0 / fma(_1829, _1121, _925 * length(float3(_1099 * float2(dot(_1078, _1748), dot(_1091, _1748)), 128.0 * _1829)))))) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1757 * _1757) / fast::max(_1743, 9.9999997473787516355514526367188e-05)) * _1776) * _1776)) * _1829), float3(65504.0));
    out.fragColor = float4(_1979, 1.0);
    return out;
}

