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
    float _1130 = _957.y;
    float _1135 = _957.z;
    float _1140 = _957.x;
    float _1258 = fast::max(dot(_957, _963), 9.9999997473787516355514526367188e-05);
    float3 _1262 = reflect(-_963, _957);
    float4 _1297 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1258, params.facet_perceptualRoughness), level(0.0));
    float3 _1316 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1297.y) - 1.0));
    float _1403 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1360 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1258, _1403), level(0.0));
    float3 _1410 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1373 = _1360.z;
    float _1375 = fma(-fast::max(_1410.x, fast::max(_1410.y, _1410.z)), _1373, 1.0);
    float _1419 = _1403 * _1403;
    float _1380 = _1360.w;
    float3 _1396 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1130)) + (frame.sh[2].xyz * _1135)) + (frame.sh[3].xyz * _1140)) + (((((frame.sh[4].xyz * (_1140 * _1130)) + (frame.sh[5].xyz * (_1130 * _1135))) + (frame.sh[6].xyz * fma(3.0 * _1135, _1135, -1.0))) + (frame.sh[7].xyz * (_1140 * _1135))) + (frame.sh[8].xyz * fma(_1140, _1140, -(_1130 * _1130)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1262, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1297.xxx, _1297.yyy, float3(params.facet_f0)) * _1316)) * _1375;
    float3 _1558 = fast::normalize(_963 + frame.lightDirection.xyz);
    float _1491 = fast::clamp(dot(_957, frame.lightDirection.xyz), 0.0, 1.0);
    float _1495 = fast::clamp(dot(_957, _1558), 0.0, 1.0);
    float3 _1596 = cross(_957, _1558);
    float _1599 = _1495 * params.facet_alpha;
    float _1608 = params.facet_alpha / fma(_1599, _1599, dot(_1596, _1596));
    float _1621 = params.facet_alpha * params.facet_alpha;
    float _1627 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1631 = sqrt(fma(_1258 * _1258, _1627, _1621));
    float _1654 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1558), 0.0, 1.0);
    float _1657 = _1654 * _1654;
    float3 _1665 = float3(1.0) - float3(params.facet_f0);
    float _1698 = 8192.0 * fma(-_1491, _1258, _1491 + _1258);
    float _1702 = 1.0 / (_1419 * _1698);
    float _1709 = 2048.0 * _1419;
    float3 _1532 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1772 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1775 = dot(_1772, _1772);
    float3 _1780 = _1772 * rsqrt(fast::max(_1775, 9.9999999392252902907785028219223e-09));
    float _1784 = _1775 * float(frame.punctualLights[0].positionFalloff.w);
    float _1789 = fast::clamp(fma(-_1784, _1784, 1.0), 0.0, 1.0);
    float _1808 = fast::clamp(fma(dot(-_1780, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1817 = float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1789 * _1789) / fast::max(_1775, 9.9999997473787516355514526367188e-05)) * _1808) * _1808);
    float3 _1940 = fast::normalize(_963 + _1780);
    float _1873 = fast::clamp(dot(_957, _1780), 0.0, 1.0);
    float _1877 = fast::clamp(dot(_957, _1940), 0.0, 1.0);
    float3 _1978 = cross(_957, _1940);
    float _1981 = _1877 * params.facet_alpha;
    float _1990 = params.facet_alpha / fma(_1981, _1981, dot(_1978, _1978));
    float _2036 = 1.0 - fast::clamp(dot(_1780, _1940), 0.0, 1.0);
    float _2039 = _2036 * _2036;
    float _2080 = 8192.0 * fma(-_1873, _1258, _1873 + _1258);
    float _2084 = 1.0 / (_1419 * _2080);
    float3 _2119 = (fma(facet_environment.sample(facet_environmentSmplr, _1262, level(_1403 * (4.0 * (2.0 - _1403)))).xyz, _1410 * _1373, _1396) + fast::min(fma(fma((float3(params.facet_f0) + (_1665 * ((_1657 * _1657) * _1654))) * (((_1608 * _1608) * 0.3183098733425140380859375) * (0.5 / fma(_1491, _1631, _1258 * sqrt(fma(_1491 * _1491, _1627, _1621))))), _1316, _1532), (frame.lightColor.xyz * _1491) * _1375, (_1410 * ((((fma(_1702, _1698, 2.0) * pow(fast::max(fma(-_1495, _1495, 1.0), 0.0), 0.5 * (_1702 * _1698))) * 0.15915493667125701904296875) * (_1491 * (_1702 * _1709))) * _1380)) * frame.lightColor.xyz), float3(65504.0))) + fast::min(fma(fma((float3(params.facet_f0) + (_1665 * ((_2039 * _2039) * _2036))) * (((_1990 * _1990) * 0.3183098733425140380859375) * (0.5 / fma(_1873, _1631, _1258 * sqrt(fma(_1873 * _1873, _1627, _1621))))), _1316, _1532), (_1817 * _1873) * _1375, (_1410 * ((((fma(_2084, _2080, 2.0) * pow(fast::max(fma(-_1877, _1877, 1.0), 0.0), 0.5 * (_2084 * _2080))) * 0.15915493667125701904296875) * (_1873 * (_2084 * _1709))) * _1380)) * _1817), float3(65504.0));
    float3 _2154 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2157 = dot(_2154, _2154);
    float3 _2162 = _2154 * rsqrt(fast::max(_2157, 9.9999999392252902907785028219223e-09));
    float _2166 = _2157 * float(frame.punctualLights[1].positionFalloff.w);
    float _2171 = fast::clamp(fma(-_2166, _2166, 1.0), 0.0, 1.0);
    float _2190 = fast::clamp(fma(dot(-_2162, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2199 = float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2171 * _2171) / fast::max(_2157, 9.9999997473787516355514526367188e-05)) * _2190) * _2190);
    float3 _2322 = fast::normalize(_963 + _2162);
    float _2255 = fast::clamp(dot(_957, _2162), 0.0, 1.0);
    float _2259 = fast::clamp(dot(_957, _2322), 0.0, 1.0);
    float3 _2360 = cross(_957, _2322);
    float _2363 = _2259 * params.facet_alpha;
    float _2372 = params.facet_alpha / fma(_2363, _2363, dot(_2360, _2360));
    float _2418 = 1.0 - fast::clamp(dot(_2162, _2322), 0.0, 1.0);
    float _2421 = _2418 * _2418;
    float _2462 = 8192.0 * fma(-_2255, _1258, _2255 + _1258);
    float _2466 = 1.0 / (_1419 * _2462);
    out.fragColor = float4(_2119 + fast::min(fma(fma((float3(params.facet_f0) + (_1665 * ((_2421 * _2421) * _2418))) * (((_2372 * _2372) * 0.3183098733425140380859375) * (0.5 / fma(_2255, _1631, _1258 * sqrt(fma(_2255 * _2255, _1627, _1621))))), _1316, _1532), (_2199 * _2255) * _1375, (_1410 * ((((fma(_2466, _2462, 2.0) * pow(fast::max(fma(-_2259, _2259, 1.0), 0.0), 0.5 * (_2466 * _2462))) * 0.15915493667125701904296875) * (_2255 * (_2466 * _1709))) * _1380)) * _2199), float3(65504.0)), 1.0);
    return out;
}

