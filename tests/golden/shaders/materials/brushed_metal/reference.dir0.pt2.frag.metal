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
    float3 _935 = fast::normalize(in.v_normal);
    float3 _941 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float3 _1083 = in.v_tangent.xyz - (_935 * dot(_935, in.v_tangent.xyz));
    float _1085 = _935.z;
    float3 _2190;
    if (abs(_1085) < 0.5)
    {
        _2190 = float3(-_935.y, _935.x, 0.0);
    }
    else
    {
        _2190 = float3(0.0, -_1085, _935.y);
    }
    float3 _1112 = fast::normalize(select(_2190, _1083, bool3(dot(_1083, _1083) > 0.001000000047497451305389404296875)));
    float _961 = fast::max(dot(_935, _941), 9.9999997473787516355514526367188e-05);
    float3 _1125 = cross(_935, _1112);
    float _1176 = fast::clamp(params.anisotropy, -1.0, 1.0);
    float2 _1171 = fast::clamp(float2(1.0 + _1176, 1.0 - _1176) * params.facet_alpha, float2(0.007921000011265277862548828125), float2(1.0));
    float2 _1131 = float2(1.0) / _1171;
    float2 _1133 = _1171 * 128.0;
    float _1139 = 0.3183098733425140380859375 * (_1131.x * _1131.y);
    float _1155 = length(float3(_1133 * float2(dot(_1112, _941), dot(_1125, _941)), 128.0 * _961));
    float3 _2206 = select(_1125, _1112, bool3(_1176 >= 0.0));
    float _1405 = dot(_2206, _941);
    float _1412 = fast::min(abs(_1176) * fast::clamp(5.0 * params.facet_perceptualRoughness, 0.0, 1.0), 0.9921875);
    float _1417 = fma(-_1412, 1.0 - _961, 1.0);
    float _1420 = _1412 * _1405;
    float4 _1460 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_961, params.facet_perceptualRoughness), level(0.0));
    float3 _1535 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1538 = dot(_1535, _1535);
    float3 _1543 = _1535 * rsqrt(fast::max(_1538, 9.9999999392252902907785028219223e-09));
    float _1547 = _1538 * float(frame.punctualLights[0].positionFalloff.w);
    float _1552 = fast::clamp(fma(-_1547, _1547, 1.0), 0.0, 1.0);
    float _1571 = fast::clamp(fma(dot(-_1543, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1677 = fast::normalize(_941 + _1543);
    float _1627 = fast::clamp(dot(_935, _1543), 0.0, 1.0);
    float _1631 = fast::clamp(dot(_935, _1677), 0.0, 1.0);
    float2 _1694 = float2(dot(_1112, _1677), dot(_1125, _1677)) * _1131;
    float _1702 = 1.0 / fma(_1631, _1631, dot(_1694, _1694));
    float _1741 = 1.0 - fast::clamp(dot(_1543, _1677), 0.0, 1.0);
    float _1744 = _1741 * _1741;
    float3 _1752 = float3(1.0) - float3(params.facet_f0);
    float3 _1809 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1812 = dot(_1809, _1809);
    float3 _1817 = _1809 * rsqrt(fast::max(_1812, 9.9999999392252902907785028219223e-09));
    float _1821 = _1812 * float(frame.punctualLights[1].positionFalloff.w);
    float _1826 = fast::clamp(fma(-_1821, _1821, 1.0), 0.0, 1.0);
    float _1845 = fast::clamp(fma(dot(-_1817, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1951 = fast::normalize(_941 + _1817);
    float _1901 = fast::clamp(dot(_935, _1817), 0.0, 1.0);
    float _1905 = fast::clamp(dot(_935, _1951), 0.0, 1.0);
    float2 _1968 = float2(dot(_1112, _1951), dot(_1125, _1951)) * _1131;
    float _1976 = 1.0 / fma(_1905, _1905, dot(_1968, _1968));
    float _2015 = 1.0 - fast::clamp(dot(_1817, _1951), 0.0, 1.0);
    float _2018 = _2015 * _2015;
    float3 _2048 = fma(facet_environment.sample(facet_environmentSmplr, ((((_935 * _1417) + (_2206 * _1420)) * (512.0 * fma(_1417, _961, _1420 * _1405))) - (_941 * (256.0 * fma(_1417, _1417, _1420 * _1420)))), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, mix(_1460.xxx, _1460.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1460.y) - 1.0))), fast::min(((float3(params.facet_f0) + (_1752 * ((_1744 * _1744) * _1741))) * (((_1139 * _1702) * _1702) * (64.0 / fma(_1627, _1155, _961 * length(float3(_1133 * float2(dot(_1112, _1543), dot(_1125, _1543)), 128.0 * _1627)))))) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1552 * _1552) / fast::max(_1538, 9.9999997473787516355514526367188e-05)) * _1571) * _1571)) * _1627), float3(65504.0))) + fast::min(((float3(params.facet_f0) + (_1752 * ((_2018 * _2018) * _2015))) * (((_1139 * _1976) * _1976) * (64.0 / fma(_1901, _1155, _961 * length(float3(_1133 * float2(dot(_1112, _1817), dot(_1125, _1817)), 128.0 * _1901)))))) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1826 * _1826) / fast::max(_1812, 9.9999997473787516355514526367188e-05)) * _1845) * _1845)) * _1901), float3(65504.0));
    out.fragColor = float4(_2048, 1.0);
    return out;
}

