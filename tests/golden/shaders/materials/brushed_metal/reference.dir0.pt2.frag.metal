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
    float3 _914 = fast::normalize(in.v_normal);
    float3 _920 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float3 _1064 = in.v_tangent.xyz - (_914 * dot(_914, in.v_tangent.xyz));
    float _1066 = _914.z;
    float3 _2142;
    if (abs(_1066) < 0.5)
    {
        _2142 = float3(-_914.y, _914.x, 0.0);
    }
    else
    {
        _2142 = float3(0.0, -_1066, _914.y);
    }
    float3 _1093 = fast::normalize(select(_2142, _1064, bool3(dot(_1064, _1064) > 0.001000000047497451305389404296875)));
    float _940 = fast::max(dot(_914, _920), 9.9999997473787516355514526367188e-05);
    float3 _1106 = cross(_914, _1093);
    float2 _1112 = float2(1.0) / params.facet_anisotropicAlpha;
    float2 _1114 = params.facet_anisotropicAlpha * 128.0;
    float _1120 = 0.3183098733425140380859375 * (_1112.x * _1112.y);
    float _1136 = length(float3(_1114 * float2(dot(_1093, _920), dot(_1106, _920)), 128.0 * _940));
    float3 _2158 = select(_1106, _1093, bool3(params.facet_anisotropy >= 0.0));
    float _1369 = dot(_2158, _920);
    float _1376 = fma(-params.facet_anisotropicBend, 1.0 - _940, 1.0);
    float _1379 = params.facet_anisotropicBend * _1369;
    float4 _1418 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_940, params.facet_perceptualRoughness), level(0.0));
    float3 _1491 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1494 = dot(_1491, _1491);
    float3 _1499 = _1491 * rsqrt(fast::max(_1494, 9.9999999392252902907785028219223e-09));
    float _1503 = _1494 * float(frame.punctualLights[0].positionFalloff.w);
    float _1508 = fast::clamp(fma(-_1503, _1503, 1.0), 0.0, 1.0);
    float _1527 = fast::clamp(fma(dot(-_1499, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1633 = fast::normalize(_920 + _1499);
    float _1583 = fast::clamp(dot(_914, _1499), 0.0, 1.0);
    float _1587 = fast::clamp(dot(_914, _1633), 0.0, 1.0);
    float2 _1650 = float2(dot(_1093, _1633), dot(_1106, _1633)) * _1112;
    float _1658 = 1.0 / fma(_1587, _1587, dot(_1650, _1650));
    float _1697 = 1.0 - fast::clamp(dot(_1499, _1633), 0.0, 1.0);
    float _1700 = _1697 * _1697;
    float3 _1708 = float3(1.0) - float3(params.facet_f0);
    float3 _1765 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1768 = dot(_1765, _1765);
    float3 _1773 = _1765 * rsqrt(fast::max(_1768, 9.9999999392252902907785028219223e-09));
    float _1777 = _1768 * float(frame.punctualLights[1].positionFalloff.w);
    float _1782 = fast::clamp(fma(-_1777, _1777, 1.0), 0.0, 1.0);
    float _1801 = fast::clamp(fma(dot(-_1773, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1907 = fast::normalize(_920 + _1773);
    float _1857 = fast::clamp(dot(_914, _1773), 0.0, 1.0);
    float _1861 = fast::clamp(dot(_914, _1907), 0.0, 1.0);
    float2 _1924 = float2(dot(_1093, _1907), dot(_1106, _1907)) * _1112;
    float _1932 = 1.0 / fma(_1861, _1861, dot(_1924, _1924));
    float _1971 = 1.0 - fast::clamp(dot(_1773, _1907), 0.0, 1.0);
    float _1974 = _1971 * _1971;
    float3 _2004 = fma(facet_environment.sample(facet_environmentSmplr, ((((_914 * _1376) + (_2158 * _1379)) * (512.0 * fma(_1376, _940, _1379 * _1369))) - (_920 * (256.0 * fma(_1376, _1376, _1379 * _1379)))), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, mix(_1418.xxx, _1418.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1418.y) - 1.0))), fast::min(((float3(params.facet_f0) + (_1708 * ((_1700 * _1700) * _1697))) * (((_1120 * _1658) * _1658) * (64.0 / fma(_1583, _1136, _940 * length(float3(_1114 * float2(dot(_1093, _1499), dot(_1106, _1499)), 128.0 * _1583)))))) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1508 * _1508) / fast::max(_1494, 9.9999997473787516355514526367188e-05)) * _1527) * _1527)) * _1583), float3(65504.0))) + fast::min(((float3(params.facet_f0) + (_1708 * ((_1974 * _1974) * _1971))) * (((_1120 * _1932) * _1932) * (64.0 / fma(_1857, _1136, _940 * length(float3(_1114 * float2(dot(_1093, _1773), dot(_1106, _1773)), 128.0 * _1857)))))) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1782 * _1782) / fast::max(_1768, 9.9999997473787516355514526367188e-05)) * _1801) * _1801)) * _1857), float3(65504.0));
    out.fragColor = float4(_2004, 1.0);
    return out;
}

