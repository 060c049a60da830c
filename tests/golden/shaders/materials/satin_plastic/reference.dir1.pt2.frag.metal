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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    float3 _959 = fast::normalize(in.v_normal);
    float3 _965 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1132 = _959.y;
    float _1137 = _959.z;
    float _1142 = _959.x;
    float _1260 = fast::max(dot(_959, _965), 9.9999997473787516355514526367188e-05);
    float3 _1264 = reflect(-_965, _959);
    float4 _1299 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1260, params.facet_perceptualRoughness), level(0.0));
    float3 _1318 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1299.y) - 1.0));
    float _1407 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1364 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1260, _1407), level(0.0));
    float3 _1414 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1377 = _1364.z;
    float _1379 = fma(-fast::max(_1414.x, fast::max(_1414.y, _1414.z)), _1377, 1.0);
    float _1423 = _1407 * _1407;
    float _1384 = _1364.w;
    float3 _1400 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1132)) + (frame.sh[2].xyz * _1137)) + (frame.sh[3].xyz * _1142)) + (((((frame.sh[4].xyz * (_1142 * _1132)) + (frame.sh[5].xyz * (_1132 * _1137))) + (frame.sh[6].xyz * fma(3.0 * _1137, _1137, -1.0))) + (frame.sh[7].xyz * (_1142 * _1137))) + (frame.sh[8].xyz * fma(_1142, _1142, -(_1132 * _1132)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1264, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1299.xxx, _1299.yyy, float3(params.facet_f0)) * _1318)) * _1379;
    float3 _1564 = fast::normalize(_965 + frame.lightDirection.xyz);
    float _1497 = fast::clamp(dot(_959, frame.lightDirection.xyz), 0.0, 1.0);
    float _1501 = fast::clamp(dot(_959, _1564), 0.0, 1.0);
    float3 _1602 = cross(_959, _1564);
    float _1605 = _1501 * params.facet_alpha;
    float _1614 = params.facet_alpha / fma(_1605, _1605, dot(_1602, _1602));
    float _1627 = params.facet_alpha * params.facet_alpha;
    float _1633 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1637 = sqrt(fma(_1260 * _1260, _1633, _1627));
    float _1660 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1564), 0.0, 1.0);
    float _1663 = _1660 * _1660;
    float3 _1671 = float3(1.0) - float3(params.facet_f0);
    float _1704 = 8192.0 * fma(-_1497, _1260, _1497 + _1260);
    float _1708 = 1.0 / (_1423 * _1704);
    float _1715 = 2048.0 * _1423;
    float3 _1538 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1778 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1781 = dot(_1778, _1778);
    float3 _1786 = _1778 * rsqrt(fast::max(_1781, 9.9999999392252902907785028219223e-09));
    float _1790 = _1781 * float(frame.punctualLights[0].positionFalloff.w);
    float _1795 = fast::clamp(fma(-_1790, _1790, 1.0), 0.0, 1.0);
    float _1814 = fast::clamp(fma(dot(-_1786, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1823 = float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1795 * _1795) / fast::max(_1781, 9.9999997473787516355514526367188e-05)) * _1814) * _1814);
    float3 _1946 = fast::normalize(_965 + _1786);
    float _1879 = fast::clamp(dot(_959, _1786), 0.0, 1.0);
    float _1883 = fast::clamp(dot(_959, _1946), 0.0, 1.0);
    float3 _1984 = cross(_959, _1946);
    float _1987 = _1883 * params.facet_alpha;
    float _1996 = params.facet_alpha / fma(_1987, _1987, dot(_1984, _1984));
    float _2042 = 1.0 - fast::clamp(dot(_1786, _1946), 0.0, 1.0);
    float _2045 = _2042 * _2042;
    float _2086 = 8192.0 * fma(-_1879, _1260, _1879 + _1260);
    float _2090 = 1.0 / (_1423 * _2086);
    float3 _2125 = (fma(facet_environment.sample(facet_environmentSmplr, _1264, level(_1407 * (4.0 * (2.0 - _1407)))).xyz, _1414 * _1377, _1400) + fast::min(fma(fma((float3(params.facet_f0) + (_1671 * ((_1663 * _1663) * _1660))) * (((_1614 * _1614) * 0.3183098733425140380859375) * (0.5 / fma(_1497, _1637, _1260 * sqrt(fma(_1497 * _1497, _1633, _1627))))), _1318, _1538), (frame.lightColor.xyz * _1497) * _1379, (_1414 * ((((fma(_1708, _1704, 2.0) * pow(fast::max(fma(-_1501, _1501, 1.0), 0.0), 0.5 * (_1708 * _1704))) * 0.15915493667125701904296875) * (_1497 * (_1708 * _1715))) * _1384)) * frame.lightColor.xyz), float3(65504.0))) + fast::min(fma(fma((float3(params.facet_f0) + (_1671 * ((_2045 * _2045) * _2042))) * (((_1996 * _1996) * 0.3183098733425140380859375) * (0.5 / fma(_1879, _1637, _1260 * sqrt(fma(_1879 * _1879, _1633, _1627))))), _1318, _1538), (_1823 * _1879) * _1379, (_1414 * ((((fma(_2090, _2086, 2.0) * pow(fast::max(fma(-_1883, _1883, 1.0), 0.0), 0.5 * (_2090 * _2086))) * 0.15915493667125701904296875) * (_1879 * (_2090 * _1715))) * _1384)) * _1823), float3(65504.0));
    float3 _2160 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2163 = dot(_2160, _2160);
    float3 _2168 = _2160 * rsqrt(fast::max(_2163, 9.9999999392252902907785028219223e-09));
    float _2172 = _2163 * float(frame.punctualLights[1].positionFalloff.w);
    float _2177 = fast::clamp(fma(-_2172, _2172, 1.0), 0.0, 1.0);
    float _2196 = fast::clamp(fma(dot(-_2168, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2205 = float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2177 * _2177) / fast::max(_2163, 9.9999997473787516355514526367188e-05)) * _2196) * _2196);
    float3 _2328 = fast::normalize(_965 + _2168);
    float _2261 = fast::clamp(dot(_959, _2168), 0.0, 1.0);
    float _2265 = fast::clamp(dot(_959, _2328), 0.0, 1.0);
    float3 _2366 = cross(_959, _2328);
    float _2369 = _2265 * params.facet_alpha;
    float _2378 = params.facet_alpha / fma(_2369, _2369, dot(_2366, _2366));
    float _2424 = 1.0 - fast::clamp(dot(_2168, _2328), 0.0, 1.0);
    float _2427 = _2424 * _2424;
    float _2468 = 8192.0 * fma(-_2261, _1260, _2261 + _1260);
    float _2472 = 1.0 / (_1423 * _2468);
    out.fragColor = float4(_2125 + fast::min(fma(fma((float3(params.facet_f0) + (_1671 * ((_2427 * _2427) * _2424))) * (((_2378 * _2378) * 0.3183098733425140380859375) * (0.5 / fma(_2261, _1637, _1260 * sqrt(fma(_2261 * _2261, _1633, _1627))))), _1318, _1538), (_2205 * _2261) * _1379, (_1414 * ((((fma(_2472, _2468, 2.0) * pow(fast::max(fma(-_2265, _2265, 1.0), 0.0), 0.5 * (_2472 * _2468))) * 0.15915493667125701904296875) * (_2261 * (_2472 * _1715))) * _1384)) * _2205), float3(65504.0)), 1.0);
    return out;
}

