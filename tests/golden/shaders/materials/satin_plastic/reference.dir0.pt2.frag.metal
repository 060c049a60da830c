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
    float3 _972 = fast::normalize(in.v_normal);
    float3 _978 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1124 = _972.y;
    float _1129 = _972.z;
    float _1134 = _972.x;
    float _1252 = fast::max(dot(_972, _978), 9.9999997473787516355514526367188e-05);
    float3 _1256 = reflect(-_978, _972);
    float4 _1291 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1252, params.facet_perceptualRoughness), level(0.0));
    float3 _1310 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1291.y) - 1.0));
    float _1394 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1351 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1252, _1394), level(0.0));
    float3 _1401 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1364 = _1351.z;
    float _1366 = fma(-fast::max(_1401.x, fast::max(_1401.y, _1401.z)), _1364, 1.0);
    float _1410 = _1394 * _1394;
    float _1371 = _1351.w;
    float3 _1387 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1124)) + (frame.sh[2].xyz * _1129)) + (frame.sh[3].xyz * _1134)) + (((((frame.sh[4].xyz * (_1134 * _1124)) + (frame.sh[5].xyz * (_1124 * _1129))) + (frame.sh[6].xyz * fma(3.0 * _1129, _1129, -1.0))) + (frame.sh[7].xyz * (_1134 * _1129))) + (frame.sh[8].xyz * fma(_1134, _1134, -(_1124 * _1124)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1256, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1291.xxx, _1291.yyy, float3(params.facet_f0)) * _1310)) * _1366;
    float3 _1458 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1461 = dot(_1458, _1458);
    float3 _1466 = _1458 * rsqrt(fast::max(_1461, 9.9999999392252902907785028219223e-09));
    float _1470 = _1461 * float(frame.punctualLights[0].positionFalloff.w);
    float _1475 = fast::clamp(fma(-_1470, _1470, 1.0), 0.0, 1.0);
    float _1494 = fast::clamp(fma(dot(-_1466, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1503 = float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1475 * _1475) / fast::max(_1461, 9.9999997473787516355514526367188e-05)) * _1494) * _1494);
    float3 _1626 = fast::normalize(_978 + _1466);
    float _1559 = fast::clamp(dot(_972, _1466), 0.0, 1.0);
    float _1563 = fast::clamp(dot(_972, _1626), 0.0, 1.0);
    float _1664 = 4096.0 * params.facet_alpha;
    float4 _1688 = float4(cross(_972, _1626), params.facet_alpha * _1563) * 64.0;
    float _1670 = _1664 / dot(_1688, _1688);
    float _1699 = params.facet_alpha * params.facet_alpha;
    float _1705 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1709 = sqrt(fma(_1252 * _1252, _1705, _1699));
    float _1732 = 1.0 - fast::clamp(dot(_1466, _1626), 0.0, 1.0);
    float _1735 = _1732 * _1732;
    float3 _1743 = float3(1.0) - float3(params.facet_f0);
    float _1776 = 8192.0 * fma(-_1559, _1252, _1559 + _1252);
    float _1780 = 1.0 / (_1410 * _1776);
    float _1787 = 2048.0 * _1410;
    float3 _1600 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1850 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1853 = dot(_1850, _1850);
    float3 _1858 = _1850 * rsqrt(fast::max(_1853, 9.9999999392252902907785028219223e-09));
    float _1862 = _1853 * float(frame.punctualLights[1].positionFalloff.w);
    float _1867 = fast::clamp(fma(-_1862, _1862, 1.0), 0.0, 1.0);
    float _1886 = fast::clamp(fma(dot(-_1858, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1895 = float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1867 * _1867) / fast::max(_1853, 9.9999997473787516355514526367188e-05)) * _1886) * _1886);
    float3 _2018 = fast::normalize(_978 + _1858);
    float _1951 = fast::clamp(dot(_972, _1858), 0.0, 1.0);
    float _1955 = fast::clamp(dot(_972, _2018), 0.0, 1.0);
    float4 _2080 = float4(cross(_972, _2018), params.facet_alpha * _1955) * 64.0;
    float _2062 = _1664 / dot(_2080, _2080);
    float _2124 = 1.0 - fast::clamp(dot(_1858, _2018), 0.0, 1.0);
    float _2127 = _2124 * _2124;
    float _2168 = 8192.0 * fma(-_1951, _1252, _1951 + _1252);
    float _2172 = 1.0 / (_1410 * _2168);
    float3 _2207 = (fma(facet_environment.sample(facet_environmentSmplr, _1256, level(_1394 * 4.0)).xyz, _1401 * _1364, _1387) + fast::min(fma(fma((float3(params.facet_f0) + (_1743 * ((_1735 * _1735) * _1732))) * (((_1670 * _1670) * 0.3183098733425140380859375) * (0.5 / fma(_1559, _1709, _1252 * sqrt(fma(_1559 * _1559, _1705, _1699))))), _1310, _1600), (_1503 * _1559) * _1366, (_1401 * ((((fma(_1780, _1776, 2.0) * pow(fast::max(fma(-_1563, _1563, 1.0), 0.0), 0.5 * (_1780 * _1776))) * 0.15915493667125701904296875) * (_1559 * (_1780 * _1787))) * _1371)) * _1503), float3(65504.0))) + fast::min(fma(fma((float3(params.facet_f0) + (_1743 * ((_2127 * _2127) * _2124))) * (((_2062 * _2062) * 0.3183098733425140380859375) * (0.5 / fma(_1951, _1709, _1252 * sqrt(fma(_1951 * _1951, _1705, _1699))))), _1310, _1600), (_1895 * _1951) * _1366, (_1401 * ((((fma(_2172, _2168, 2.0) * pow(fast::max(fma(-_1955, _1955, 1.0), 0.0), 0.5 * (_2172 * _2168))) * 0.15915493667125701904296875) * (_1951 * (_2172 * _1787))) * _1371)) * _1895), float3(65504.0));
    out.fragColor = float4(_2207, 1.0);
    return out;
}

