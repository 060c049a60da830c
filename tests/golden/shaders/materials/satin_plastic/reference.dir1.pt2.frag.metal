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
    float3 _975 = fast::normalize(in.v_normal);
    float3 _981 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1148 = _975.y;
    float _1153 = _975.z;
    float _1158 = _975.x;
    float _1276 = fast::max(dot(_975, _981), 9.9999997473787516355514526367188e-05);
    float3 _1280 = reflect(-_981, _975);
    float4 _1315 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1276, params.facet_perceptualRoughness), level(0.0));
    float3 _1334 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1315.y) - 1.0));
    float _1421 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1378 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1276, _1421), level(0.0));
    float3 _1428 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1391 = _1378.z;
    float _1393 = fma(-fast::max(_1428.x, fast::max(_1428.y, _1428.z)), _1391, 1.0);
    float _1437 = _1421 * _1421;
    float _1398 = _1378.w;
    float3 _1414 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1148)) + (frame.sh[2].xyz * _1153)) + (frame.sh[3].xyz * _1158)) + (((((frame.sh[4].xyz * (_1158 * _1148)) + (frame.sh[5].xyz * (_1148 * _1153))) + (frame.sh[6].xyz * fma(3.0 * _1153, _1153, -1.0))) + (frame.sh[7].xyz * (_1158 * _1153))) + (frame.sh[8].xyz * fma(_1158, _1158, -(_1148 * _1148)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1280, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1315.xxx, _1315.yyy, float3(params.facet_f0)) * _1334)) * _1393;
    float3 _1576 = fast::normalize(_981 + frame.lightDirection.xyz);
    float _1509 = fast::clamp(dot(_975, frame.lightDirection.xyz), 0.0, 1.0);
    float _1513 = fast::clamp(dot(_975, _1576), 0.0, 1.0);
    float _1614 = 4096.0 * params.facet_alpha;
    float4 _1638 = float4(cross(_975, _1576), params.facet_alpha * _1513) * 64.0;
    float _1620 = _1614 / dot(_1638, _1638);
    float _1649 = params.facet_alpha * params.facet_alpha;
    float _1655 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1659 = sqrt(fma(_1276 * _1276, _1655, _1649));
    float _1682 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1576), 0.0, 1.0);
    float _1685 = _1682 * _1682;
    float3 _1693 = float3(1.0) - float3(params.facet_f0);
    float _1726 = 8192.0 * fma(-_1509, _1276, _1509 + _1276);
    float _1730 = 1.0 / (_1437 * _1726);
    float _1737 = 2048.0 * _1437;
    float3 _1550 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1800 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1803 = dot(_1800, _1800);
    float3 _1808 = _1800 * rsqrt(fast::max(_1803, 9.9999999392252902907785028219223e-09));
    float _1812 = _1803 * float(frame.punctualLights[0].positionFalloff.w);
    float _1817 = fast::clamp(fma(-_1812, _1812, 1.0), 0.0, 1.0);
    float _1836 = fast::clamp(fma(dot(-_1808, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1845 = float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1817 * _1817) / fast::max(_1803, 9.9999997473787516355514526367188e-05)) * _1836) * _1836);
    float3 _1968 = fast::normalize(_981 + _1808);
    float _1901 = fast::clamp(dot(_975, _1808), 0.0, 1.0);
    float _1905 = fast::clamp(dot(_975, _1968), 0.0, 1.0);
    float4 _2030 = float4(cross(_975, _1968), params.facet_alpha * _1905) * 64.0;
    float _2012 = _1614 / dot(_2030, _2030);
    float _2074 = 1.0 - fast::clamp(dot(_1808, _1968), 0.0, 1.0);
    float _2077 = _2074 * _2074;
    float _2118 = 8192.0 * fma(-_1901, _1276, _1901 + _1276);
    float _2122 = 1.0 / (_1437 * _2118);
    float3 _2157 = (fma(facet_environment.sample(facet_environmentSmplr, _1280, level(_1421 * (4.0 * (2.0 - _1421)))).xyz, _1428 * _1391, _1414) + fast::min(fma(fma((float3(params.facet_f0) + (_1693 * ((_1685 * _1685) * _1682))) * (((_1620 * _1620) * 0.3183098733425140380859375) * (0.5 / fma(_1509, _1659, _1276 * sqrt(fma(_1509 * _1509, _1655, _1649))))), _1334, _1550), (frame.lightColor.xyz * _1509) * _1393, (_1428 * ((((fma(_1730, _1726, 2.0) * pow(fast::max(fma(-_1513, _1513, 1.0), 0.0), 0.5 * (_1730 * _1726))) * 0.15915493667125701904296875) * (_1509 * (_1730 * _1737))) * _1398)) * frame.lightColor.xyz), float3(65504.0))) + fast::min(fma(fma((float3(params.facet_f0) + (_1693 * ((_2077 * _2077) * _2074))) * (((_2012 * _2012) * 0.3183098733425140380859375) * (0.5 / fma(_1901, _1659, _1276 * sqrt(fma(_1901 * _1901, _1655, _1649))))), _1334, _1550), (_1845 * _1901) * _1393, (_1428 * ((((fma(_2122, _2118, 2.0) * pow(fast::max(fma(-_1905, _1905, 1.0), 0.0), 0.5 * (_2122 * _2118))) * 0.15915493667125701904296875) * (_1901 * (_2122 * _1737))) * _1398)) * _1845), float3(65504.0));
    float3 _2192 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2195 = dot(_2192, _2192);
    float3 _2200 = _2192 * rsqrt(fast::max(_2195, 9.9999999392252902907785028219223e-09));
    float _2204 = _2195 * float(frame.punctualLights[1].positionFalloff.w);
    float _2209 = fast::clamp(fma(-_2204, _2204, 1.0), 0.0, 1.0);
    float _2228 = fast::clamp(fma(dot(-_2200, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2237 = float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2209 * _2209) / fast::max(_2195, 9.9999997473787516355514526367188e-05)) * _2228) * _2228);
    float3 _2360 = fast::normalize(_981 + _2200);
    float _2293 = fast::clamp(dot(_975, _2200), 0.0, 1.0);
    float _2297 = fast::clamp(dot(_975, _2360), 0.0, 1.0);
    float4 _2422 = float4(cross(_975, _2360), params.facet_alpha * _2297) * 64.0;
    float _2404 = _1614 / dot(_2422, _2422);
    float _2466 = 1.0 - fast::clamp(dot(_2200, _2360), 0.0, 1.0);
    float _2469 = _2466 * _2466;
    float _2510 = 8192.0 * fma(-_2293, _1276, _2293 + _1276);
    float _2514 = 1.0 / (_1437 * _2510);
    out.fragColor = float4(_2157 + fast::min(fma(fma((float3(params.facet_f0) + (_1693 * ((_2469 * _2469) * _2466))) * (((_2404 * _2404) * 0.3183098733425140380859375) * (0.5 / fma(_2293, _1659, _1276 * sqrt(fma(_2293 * _2293, _1655, _1649))))), _1334, _1550), (_2237 * _2293) * _1393, (_1428 * ((((fma(_2514, _2510, 2.0) * pow(fast::max(fma(-_2297, _2297, 1.0), 0.0), 0.5 * (_2514 * _2510))) * 0.15915493667125701904296875) * (_2293 * (_2514 * _1737))) * _1398)) * _2237), float3(65504.0)), 1.0);
    return out;
}

