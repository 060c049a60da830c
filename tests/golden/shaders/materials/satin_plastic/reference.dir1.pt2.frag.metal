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
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
    float facet_sheenRoughness;
    float facet_sheenAlpha;
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
    float3 _968 = fast::normalize(in.v_normal);
    float3 _974 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1142 = _968.y;
    float _1147 = _968.z;
    float _1152 = _968.x;
    float _1270 = fast::max(dot(_968, _974), 9.9999997473787516355514526367188e-05);
    float3 _1274 = reflect(-_974, _968);
    float4 _1309 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1270, params.facet_perceptualRoughness), level(0.0));
    float3 _1328 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1309.y) - 1.0));
    float4 _1370 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1270, params.facet_sheenRoughness), level(0.0));
    float _1383 = _1370.z;
    float _1385 = fma(-fast::max(params.facet_sheenColor[0], fast::max(params.facet_sheenColor[1], params.facet_sheenColor[2])), _1383, 1.0);
    float _1390 = _1370.w;
    float3 _1409 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1142)) + (frame.sh[2].xyz * _1147)) + (frame.sh[3].xyz * _1152)) + (((((frame.sh[4].xyz * (_1152 * _1142)) + (frame.sh[5].xyz * (_1142 * _1147))) + (frame.sh[6].xyz * fma(3.0 * _1147, _1147, -1.0))) + (frame.sh[7].xyz * (_1152 * _1147))) + (frame.sh[8].xyz * fma(_1152, _1152, -(_1142 * _1142)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1274, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1309.xxx, _1309.yyy, float3(params.facet_f0)) * _1328)) * _1385;
    float3 _1546 = fast::normalize(_974 + frame.lightDirection.xyz);
    float _1479 = fast::clamp(dot(_968, frame.lightDirection.xyz), 0.0, 1.0);
    float _1483 = fast::clamp(dot(_968, _1546), 0.0, 1.0);
    float _1584 = 4096.0 * params.facet_alpha;
    float4 _1608 = float4(cross(_968, _1546), params.facet_alpha * _1483) * 64.0;
    float _1590 = _1584 / dot(_1608, _1608);
    float _1619 = params.facet_alpha * params.facet_alpha;
    float _1625 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1629 = sqrt(fma(_1270 * _1270, _1625, _1619));
    float _1652 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1546), 0.0, 1.0);
    float _1655 = _1652 * _1652;
    float3 _1663 = float3(1.0) - float3(params.facet_f0);
    float _1696 = 8192.0 * fma(-_1479, _1270, _1479 + _1270);
    float _1700 = 1.0 / (params.facet_sheenAlpha * _1696);
    float _1707 = 2048.0 * params.facet_sheenAlpha;
    float3 _1520 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1770 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1773 = dot(_1770, _1770);
    float3 _1778 = _1770 * rsqrt(fast::max(_1773, 9.9999999392252902907785028219223e-09));
    float _1782 = _1773 * float(frame.punctualLights[0].positionFalloff.w);
    float _1787 = fast::clamp(fma(-_1782, _1782, 1.0), 0.0, 1.0);
    float _1806 = fast::clamp(fma(dot(-_1778, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1815 = float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1787 * _1787) / fast::max(_1773, 9.9999997473787516355514526367188e-05)) * _1806) * _1806);
    float3 _1938 = fast::normalize(_974 + _1778);
    float _1871 = fast::clamp(dot(_968, _1778), 0.0, 1.0);
    float _1875 = fast::clamp(dot(_968, _1938), 0.0, 1.0);
    float4 _2000 = float4(cross(_968, _1938), params.facet_alpha * _1875) * 64.0;
    float _1982 = _1584 / dot(_2000, _2000);
    float _2044 = 1.0 - fast::clamp(dot(_1778, _1938), 0.0, 1.0);
    float _2047 = _2044 * _2044;
    float _2088 = 8192.0 * fma(-_1871, _1270, _1871 + _1270);
    float _2092 = 1.0 / (params.facet_sheenAlpha * _2088);
    float3 _2127 = (fma(facet_environment.sample(facet_environmentSmplr, _1274, level(params.facet_sheenLod)).xyz, float3(params.facet_sheenColor) * _1383, _1409) + fast::min(fma(fma((float3(params.facet_f0) + (_1663 * ((_1655 * _1655) * _1652))) * (((_1590 * _1590) * 0.3183098733425140380859375) * (0.5 / fma(_1479, _1629, _1270 * sqrt(fma(_1479 * _1479, _1625, _1619))))), _1328, _1520), (frame.lightColor.xyz * _1479) * _1385, (float3(params.facet_sheenColor) * ((((fma(_1700, _1696, 2.0) * pow(fast::max(fma(-_1483, _1483, 1.0), 0.0), 0.5 * (_1700 * _1696))) * 0.15915493667125701904296875) * (_1479 * (_1700 * _1707))) * _1390)) * frame.lightColor.xyz), float3(65504.0))) + fast::min(fma(fma((float3(params.facet_f0) + (_1663 * ((_2047 * _2047) * _2044))) * (((_1982 * _1982) * 0.3183098733425140380859375) * (0.5 / fma(_1871, _1629, _1270 * sqrt(fma(_1871 * _1871, _1625, _1619))))), _1328, _1520), (_1815 * _1871) * _1385, (float3(params.facet_sheenColor) * ((((fma(_2092, _2088, 2.0) * pow(fast::max(fma(-_1875, _1875, 1.0), 0.0), 0.5 * (_2092 * _2088))) * 0.15915493667125701904296875) * (_1871 * (_2092 * _1707))) * _1390)) * _1815), float3(65504.0));
    float3 _2162 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2165 = dot(_2162, _2162);
    float3 _2170 = _2162 * rsqrt(fast::max(_2165, 9.9999999392252902907785028219223e-09));
    float _2174 = _2165 * float(frame.punctualLights[1].positionFalloff.w);
    float _2179 = fast::clamp(fma(-_2174, _2174, 1.0), 0.0, 1.0);
    float _2198 = fast::clamp(fma(dot(-_2170, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2207 = float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2179 * _2179) / fast::max(_2165, 9.9999997473787516355514526367188e-05)) * _2198) * _2198);
    float3 _2330 = fast::normalize(_974 + _2170);
    float _2263 = fast::clamp(dot(_968, _2170), 0.0, 1.0);
    float _2267 = fast::clamp(dot(_968, _2330), 0.0, 1.0);
    float4 _2392 = float4(cross(_968, _2330), params.facet_alpha * _2267) * 64.0;
    float _2374 = _1584 / dot(_2392, _2392);
    float _2436 = 1.0 - fast::clamp(dot(_2170, _2330), 0.0, 1.0);
    float _2439 = _2436 * _2436;
    float _2480 = 8192.0 * fma(-_2263, _1270, _2263 + _1270);
    float _2484 = 1.0 / (params.facet_sheenAlpha * _2480);
    out.fragColor = float4(_2127 + fast::min(fma(fma((float3(params.facet_f0) + (_1663 * ((_2439 * _2439) * _2436))) * (((_2374 * _2374) * 0.3183098733425140380859375) * (0.5 / fma(_2263, _1629, _1270 * sqrt(fma(_2263 * _2263, _1625, _1619))))), _1328, _1520), (_2207 * _2263) * _1385, (float3(params.facet_sheenColor) * ((((fma(_2484, _2480, 2.0) * pow(fast::max(fma(-_2267, _2267, 1.0), 0.0), 0.5 * (_2484 * _2480))) * 0.15915493667125701904296875) * (_2263 * (_2484 * _1707))) * _1390)) * _2207), float3(65504.0)), 1.0);
    return out;
}

