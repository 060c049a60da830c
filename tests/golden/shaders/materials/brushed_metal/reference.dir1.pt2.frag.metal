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
    float3 _929 = fast::normalize(in.v_normal);
    float3 _935 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float3 _1099 = in.v_tangent.xyz - (_929 * dot(_929, in.v_tangent.xyz));
    float _1101 = _929.z;
    float3 _2399;
    if (abs(_1101) < 0.5)
    {
        _2399 = float3(-_929.y, _929.x, 0.0);
    }
    else
    {
        _2399 = float3(0.0, -_1101, _929.y);
    }
    float3 _1128 = fast::normalize(select(_2399, _1099, bool3(dot(_1099, _1099) > 0.001000000047497451305389404296875)));
    float _955 = fast::max(dot(_929, _935), 9.9999997473787516355514526367188e-05);
    float3 _1141 = cross(_929, _1128);
    float _1192 = fast::clamp(params.anisotropy, -1.0, 1.0);
    float2 _1187 = fast::clamp(float2(1.0 + _1192, 1.0 - _1192) * params.facet_alpha, float2(0.007921000011265277862548828125), float2(1.0));
    float2 _1147 = float2(1.0) / _1187;
    float2 _1149 = _1187 * 128.0;
    float _1155 = 0.3183098733425140380859375 * (_1147.x * _1147.y);
    float _1171 = length(float3(_1149 * float2(dot(_1128, _935), dot(_1141, _935)), 128.0 * _955));
    float3 _2415 = select(_1141, _1128, bool3(_1192 >= 0.0));
    float _1421 = dot(_2415, _935);
    float _1428 = fast::min(abs(_1192) * fast::clamp(5.0 * params.facet_perceptualRoughness, 0.0, 1.0), 0.9921875);
    float _1433 = fma(-_1428, 1.0 - _955, 1.0);
    float _1436 = _1428 * _1421;
    float4 _1476 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_955, params.facet_perceptualRoughness), level(0.0));
    float3 _1608 = fast::normalize(_935 + frame.lightDirection.xyz);
    float _1558 = fast::clamp(dot(_929, frame.lightDirection.xyz), 0.0, 1.0);
    float _1562 = fast::clamp(dot(_929, _1608), 0.0, 1.0);
    float2 _1625 = float2(dot(_1128, _1608), dot(_1141, _1608)) * _1147;
    float _1633 = 1.0 / fma(_1562, _1562, dot(_1625, _1625));
    float _1672 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1608), 0.0, 1.0);
    float _1675 = _1672 * _1672;
    float3 _1683 = float3(1.0) - float3(params.facet_f0);
    float3 _1740 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1743 = dot(_1740, _1740);
    float3 _1748 = _1740 * rsqrt(fast::max(_1743, 9.9999999392252902907785028219223e-09));
    float _1752 = _1743 * float(frame.punctualLights[0].positionFalloff.w);
    float _1757 = fast::clamp(fma(-_1752, _1752, 1.0), 0.0, 1.0);
    float _1776 = fast::clamp(fma(dot(-_1748, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1882 = fast::normalize(_935 + _1748);
    float _1832 = fast::clamp(dot(_929, _1748), 0.0, 1.0);
    float _1836 = fast::clamp(dot(_929, _1882), 0.0, 1.0);
    float2 _1899 = float2(dot(_1128, _1882), dot(_1141, _1882)) * _1147;
    float _1907 = 1.0 / fma(_1836, _1836, dot(_1899, _1899));
    float _1946 = 1.0 - fast::clamp(dot(_1748, _1882), 0.0, 1.0);
    float _1949 = _1946 * _1946;
    float3 _1979 = fma(facet_environment.sample(facet_environmentSmplr, ((((_929 * _1433) + (_2415 * _1436)) * (512.0 * fma(_1433, _955, _1436 * _1421))) - (_935 * (256.0 * fma(_1433, _1433, _1436 * _1436)))), level(params.facet_perceptualRoughness * 4.0)).xyz, mix(_1476.xxx, _1476.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1476.y) - 1.0))), fast::min(((float3(params.facet_f0) + (_1683 * ((_1675 * _1675) * _1672))) * (((_1155 * _1633) * _1633) * (64.0 / fma(_1558, _1171, _955 * length(float3(_1149 * float2(dot(_1128, frame.lightDirection.xyz), dot(_1141, frame.lightDirection.xyz)), 128.0 * _1558)))))) * (frame.lightColor.xyz * _1558), float3(65504.0))) + fast::min(((float3(params.facet_f0) + (_1683 * ((_1949 * _1949) * _1946))) * (((_1155 * _1907) * _1907) * (64.0 / fma(_1832, _1171, _955 * length(float3(_1149 * float2(dot(_1128, _1748), dot(_1141, _1748)), 128.0 * _1832)))))) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1757 * _1757) / fast::max(_1743, 9.9999997473787516355514526367188e-05)) * _1776) * _1776)) * _1832), float3(65504.0));
    float3 _2014 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2017 = dot(_2014, _2014);
    float3 _2022 = _2014 * rsqrt(fast::max(_2017, 9.9999999392252902907785028219223e-09));
    float _2026 = _2017 * float(frame.punctualLights[1].positionFalloff.w);
    float _2031 = fast::clamp(fma(-_2026, _2026, 1.0), 0.0, 1.0);
    float _2050 = fast::clamp(fma(dot(-_2022, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2156 = fast::normalize(_935 + _2022);
    float _2106 = fast::clamp(dot(_929, _2022), 0.0, 1.0);
    float _2110 = fast::clamp(dot(_929, _2156), 0.0, 1.0);
    float2 _2173 = float2(dot(_1128, _2156), dot(_1141, _2156)) * _1147;
    float _2181 = 1.0 / fma(_2110, _2110, dot(_2173, _2173));
    float _2220 = 1.0 - fast::clamp(dot(_2022, _2156), 0.0, 1.0);
    float _2223 = _2220 * _2220;
    out.fragColor = float4(_1979 + fast::min(((float3(params.facet_f0) + (_1683 * ((_2223 * _2223) * _2220))) * (((_1155 * _2181) * _2181) * (64.0 / fma(_2106, _1171, _955 * length(float3(_1149 * float2(dot(_1128, _2022), dot(_1141, _2022)), 128.0 * _2106)))))) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2031 * _2031) / fast::max(_2017, 9.9999997473787516355514526367188e-05)) * _2050) * _2050)) * _2106), float3(65504.0)), 1.0);
    return out;
}

