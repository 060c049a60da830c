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
    float3 _957 = fast::normalize(in.v_normal);
    float3 _963 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1109 = _957.y;
    float _1114 = _957.z;
    float _1119 = _957.x;
    float _1237 = fast::max(dot(_957, _963), 9.9999997473787516355514526367188e-05);
    float3 _1241 = reflect(-_963, _957);
    float4 _1276 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1237, params.facet_perceptualRoughness), level(0.0));
    float3 _1295 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1276.y) - 1.0));
    float _1382 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1339 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1237, _1382), level(0.0));
    float3 _1389 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1352 = _1339.z;
    float _1354 = fma(-fast::max(_1389.x, fast::max(_1389.y, _1389.z)), _1352, 1.0);
    float _1398 = _1382 * _1382;
    float _1359 = _1339.w;
    float3 _1375 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1109)) + (frame.sh[2].xyz * _1114)) + (frame.sh[3].xyz * _1119)) + (((((frame.sh[4].xyz * (_1119 * _1109)) + (frame.sh[5].xyz * (_1109 * _1114))) + (frame.sh[6].xyz * fma(3.0 * _1114, _1114, -1.0))) + (frame.sh[7].xyz * (_1119 * _1114))) + (frame.sh[8].xyz * fma(_1119, _1119, -(_1109 * _1109)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1241, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1276.xxx, _1276.yyy, float3(params.facet_f0)) * _1295)) * _1354;
    float3 _1449 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1452 = dot(_1449, _1449);
    float3 _1457 = _1449 * rsqrt(fast::max(_1452, 9.9999999392252902907785028219223e-09));
    float _1461 = _1452 * float(frame.punctualLights[0].positionFalloff.w);
    float _1466 = fast::clamp(fma(-_1461, _1461, 1.0), 0.0, 1.0);
    float _1485 = fast::clamp(fma(dot(-_1457, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1494 = float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1466 * _1466) / fast::max(_1452, 9.9999997473787516355514526367188e-05)) * _1485) * _1485);
    float3 _1617 = fast::normalize(_963 + _1457);
    float _1550 = fast::clamp(dot(_957, _1457), 0.0, 1.0);
    float _1554 = fast::clamp(dot(_957, _1617), 0.0, 1.0);
    float3 _1655 = cross(_957, _1617);
    float _1658 = _1554 * params.facet_alpha;
    float _1667 = params.facet_alpha / fma(_1658, _1658, dot(_1655, _1655));
    float _1680 = params.facet_alpha * params.facet_alpha;
    float _1686 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1690 = sqrt(fma(_1237 * _1237, _1686, _1680));
    float _1713 = 1.0 - fast::clamp(dot(_1457, _1617), 0.0, 1.0);
    float _1716 = _1713 * _1713;
    float3 _1724 = float3(1.0) - float3(params.facet_f0);
    float _1757 = 8192.0 * fma(-_1550, _1237, _1550 + _1237);
    float _1761 = 1.0 / (_1398 * _1757);
    float _1768 = 2048.0 * _1398;
    float3 _1591 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1831 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1834 = dot(_1831, _1831);
    float3 _1839 = _1831 * rsqrt(fast::max(_1834, 9.9999999392252902907785028219223e-09));
    float _1843 = _1834 * float(frame.punctualLights[1].positionFalloff.w);
    float _1848 = fast::clamp(fma(-_1843, _1843, 1.0), 0.0, 1.0);
    float _1867 = fast::clamp(fma(dot(-_1839, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1876 = float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1848 * _1848) / fast::max(_1834, 9.9999997473787516355514526367188e-05)) * _1867) * _1867);
    float3 _1999 = fast::normalize(_963 + _1839);
    float _1932 = fast::clamp(dot(_957, _1839), 0.0, 1.0);
    float _1936 = fast::clamp(dot(_957, _1999), 0.0, 1.0);
    float3 _2037 = cross(_957, _1999);
    float _2040 = _1936 * params.facet_alpha;
    float _2049 = params.facet_alpha / fma(_2040, _2040, dot(_2037, _2037));
    float _2095 = 1.0 - fast::clamp(dot(_1839, _1999), 0.0, 1.0);
    float _2098 = _2095 * _2095;
    float _2139 = 8192.0 * fma(-_1932, _1237, _1932 + _1237);
    float _2143 = 1.0 / (_1398 * _2139);
    float3 _2178 = (fma(facet_environment.sample(facet_environmentSmplr, _1241, level(_1382 * (4.0 * (2.0 - _1382)))).xyz, _1389 * _1352, _1375) + fast::min(fma(fma((float3(params.facet_f0) + (_1724 * ((_1716 * _1716) * _1713))) * (((_1667 * _1667) * 0.3183098733425140380859375) * (0.5 / fma(_1550, _1690, _1237 * sqrt(fma(_1550 * _1550, _1686, _1680))))), _1295, _1591), (_1494 * _1550) * _1354, (_1389 * ((((fma(_1761, _1757, 2.0) * pow(fast::max(fma(-_1554, _1554, 1.0), 0.0), 0.5 * (_1761 * _1757))) * 0.15915493667125701904296875) * (_1550 * (_1761 * _1768))) * _1359)) * _1494), float3(65504.0))) + fast::min(fma(fma((float3(params.facet_f0) + (_1724 * ((_2098 * _2098) * _2095))) * (((_2049 * _2049) * 0.3183098733425140380859375) * (0.5 / fma(_1932, _1690, _1237 * sqrt(fma(_1932 * _1932, _1686, _1680))))), _1295, _1591), (_1876 * _1932) * _1354, (_1389 * ((((fma(_2143, _2139, 2.0) * pow(fast::max(fma(-_1936, _1936, 1.0), 0.0), 0.5 * (_2143 * _2139))) * 0.15915493667125701904296875) * (_1932 * (_2143 * _1768))) * _1359)) * _1876), float3(65504.0));
    out.fragColor = float4(_2178, 1.0);
    return out;
}

