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
    float3 _933 = fast::normalize(in.v_normal);
    float3 _939 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float3 _1102 = in.v_tangent.xyz - (_933 * dot(_933, in.v_tangent.xyz));
    float _1104 = _933.z;
    float3 _2405;
    if (abs(_1104) < 0.5)
    {
        _2405 = float3(-_933.y, _933.x, 0.0);
    }
    else
    {
        _2405 = float3(0.0, -_1104, _933.y);
    }
    float3 _1131 = fast::normalize(select(_2405, _1102, bool3(dot(_1102, _1102) > 0.001000000047497451305389404296875)));
    float _959 = fast::max(dot(_933, _939), 9.9999997473787516355514526367188e-05);
    float3 _1144 = cross(_933, _1131);
    float _1195 = fast::clamp(params.anisotropy, -1.0, 1.0);
    float2 _1190 = fast::clamp(float2(1.0 + _1195, 1.0 - _1195) * params.facet_alpha, float2(0.007921000011265277862548828125), float2(1.0));
    float2 _1150 = float2(1.0) / _1190;
    float2 _1152 = _1190 * 128.0;
    float _1158 = 0.3183098733425140380859375 * (_1150.x * _1150.y);
    float _1174 = length(float3(_1152 * float2(dot(_1131, _939), dot(_1144, _939)), 128.0 * _959));
    float3 _2421 = select(_1144, _1131, bool3(_1195 >= 0.0));
    float _1424 = dot(_2421, _939);
    float _1431 = fast::min(abs(_1195) * fast::clamp(5.0 * params.facet_perceptualRoughness, 0.0, 1.0), 0.9921875);
    float _1436 = fma(-_1431, 1.0 - _959, 1.0);
    float _1439 = _1431 * _1424;
    float4 _1479 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_959, params.facet_perceptualRoughness), level(0.0));
    float3 _1614 = fast::normalize(_939 + frame.lightDirection.xyz);
    float _1564 = fast::clamp(dot(_933, frame.lightDirection.xyz), 0.0, 1.0);
    float _1568 = fast::clamp(dot(_933, _1614), 0.0, 1.0);
    float2 _1631 = float2(dot(_1131, _1614), dot(_1144, _1614)) * _1150;
    float _1639 = 1.0 / fma(_1568, _1568, dot(_1631, _1631));
    float _1678 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1614), 0.0, 1.0);
    float _1681 = _1678 * _1678;
    float3 _1689 = float3(1.0) - float3(params.facet_f0);
    float3 _1746 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1749 = dot(_1746, _1746);
    float3 _1754 = _1746 * rsqrt(fast::max(_1749, 9.9999999392252902907785028219223e-09));
    float _1758 = _1749 * float(frame.punctualLights[0].positionFalloff.w);
    float _1763 = fast::clamp(fma(-_1758, _1758, 1.0), 0.0, 1.0);
    float _1782 = fast::clamp(fma(dot(-_1754, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1888 = fast::normalize(_939 + _1754);
    float _1838 = fast::clamp(dot(_933, _1754), 0.0, 1.0);
    float _1842 = fast::clamp(dot(_933, _1888), 0.0, 1.0);
    float2 _1905 = float2(dot(_1131, _1888), dot(_1144, _1888)) * _1150;
    float _1913 = 1.0 / fma(_1842, _1842, dot(_1905, _1905));
    float _1952 = 1.0 - fast::clamp(dot(_1754, _1888), 0.0, 1.0);
    float _1955 = _1952 * _1952;
    float3 _1985 = fma(facet_environment.sample(facet_environmentSmplr, ((((_933 * _1436) + (_2421 * _1439)) * (512.0 * fma(_1436, _959, _1439 * _1424))) - (_939 * (256.0 * fma(_1436, _1436, _1439 * _1439)))), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, mix(_1479.xxx, _1479.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1479.y) - 1.0))), fast::min(((float3(params.facet_f0) + (_1689 * ((_1681 * _1681) * _1678))) * (((_1158 * _1639) * _1639) * (64.0 / fma(_1564, _1174, _959 * length(float3(_1152 * float2(dot(_1131, frame.lightDirection.xyz), dot(_1144, frame.lightDirection.xyz)), 128.0 * _1564)))))) * (frame.lightColor.xyz * _1564), float3(65504.0))) + fast::min(((float3(params.facet_f0) + (_1689 * ((_1955 * _1955) * _1952))) * (((_1158 * _1913) * _1913) * (64.0 / fma(_1838, _1174, _959 * length(float3(_1152 * float2(dot(_1131, _1754), dot(_1144, _1754)), 128.0 * _1838)))))) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1763 * _1763) / fast::max(_1749, 9.9999997473787516355514526367188e-05)) * _1782) * _1782)) * _1838), float3(65504.0));
    float3 _2020 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2023 = dot(_2020, _2020);
    float3 _2028 = _2020 * rsqrt(fast::max(_2023, 9.9999999392252902907785028219223e-09));
    float _2032 = _2023 * float(frame.punctualLights[1].positionFalloff.w);
    float _2037 = fast::clamp(fma(-_2032, _2032, 1.0), 0.0, 1.0);
    float _2056 = fast::clamp(fma(dot(-_2028, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2162 = fast::normalize(_939 + _2028);
    float _2112 = fast::clamp(dot(_933, _2028), 0.0, 1.0);
    float _2116 = fast::clamp(dot(_933, _2162), 0.0, 1.0);
    float2 _2179 = float2(dot(_1131, _2162), dot(_1144, _2162)) * _1150;
    float _2187 = 1.0 / fma(_2116, _2116, dot(_2179, _2179));
    float _2226 = 1.0 - fast::clamp(dot(_2028, _2162), 0.0, 1.0);
    float _2229 = _2226 * _2226;
    out.fragColor = float4(_1985 + fast::min(((float3(params.facet_f0) + (_1689 * ((_2229 * _2229) * _2226))) * (((_1158 * _2187) * _2187) * (64.0 / fma(_2112, _1174, _959 * length(float3(_1152 * float2(dot(_1131, _2028), dot(_1144, _2028)), 128.0 * _2112)))))) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2037 * _2037) / fast::max(_2023, 9.9999997473787516355514526367188e-05)) * _2056) * _2056)) * _2112), float3(65504.0)), 1.0);
    return out;
}

