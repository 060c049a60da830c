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
    float3 _954 = fast::normalize(in.v_normal);
    float3 _960 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1127 = _954.y;
    float _1132 = _954.z;
    float _1137 = _954.x;
    float _1255 = fast::max(dot(_954, _960), 9.9999997473787516355514526367188e-05);
    float3 _1259 = reflect(-_960, _954);
    float4 _1294 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1255, params.facet_perceptualRoughness), level(0.0));
    float3 _1313 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1294.y) - 1.0));
    float _1397 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1354 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1255, _1397), level(0.0));
    float3 _1404 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1367 = _1354.z;
    float _1369 = fma(-fast::max(_1404.x, fast::max(_1404.y, _1404.z)), _1367, 1.0);
    float _1413 = _1397 * _1397;
    float _1374 = _1354.w;
    float3 _1390 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1127)) + (frame.sh[2].xyz * _1132)) + (frame.sh[3].xyz * _1137)) + (((((frame.sh[4].xyz * (_1137 * _1127)) + (frame.sh[5].xyz * (_1127 * _1132))) + (frame.sh[6].xyz * fma(3.0 * _1132, _1132, -1.0))) + (frame.sh[7].xyz * (_1137 * _1132))) + (frame.sh[8].xyz * fma(_1137, _1137, -(_1127 * _1127)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1259, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1294.xxx, _1294.yyy, float3(params.facet_f0)) * _1313)) * _1369;
    float3 _1549 = fast::normalize(_960 + frame.lightDirection.xyz);
    float _1482 = fast::clamp(dot(_954, frame.lightDirection.xyz), 0.0, 1.0);
    float _1486 = fast::clamp(dot(_954, _1549), 0.0, 1.0);
    float3 _1587 = cross(_954, _1549);
    float _1590 = _1486 * params.facet_alpha;
    float _1599 = params.facet_alpha / fma(_1590, _1590, dot(_1587, _1587));
    float _1612 = params.facet_alpha * params.facet_alpha;
    float _1618 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1622 = sqrt(fma(_1255 * _1255, _1618, _1612));
    float _1645 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1549), 0.0, 1.0);
    float _1648 = _1645 * _1645;
    float3 _1656 = float3(1.0) - float3(params.facet_f0);
    float _1689 = 8192.0 * fma(-_1482, _1255, _1482 + _1255);
    float _1693 = 1.0 / (_1413 * _1689);
    float _1700 = 2048.0 * _1413;
    float3 _1523 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1763 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1766 = dot(_1763, _1763);
    float3 _1771 = _1763 * rsqrt(fast::max(_1766, 9.9999999392252902907785028219223e-09));
    float _1775 = _1766 * float(frame.punctualLights[0].positionFalloff.w);
    float _1780 = fast::clamp(fma(-_1775, _1775, 1.0), 0.0, 1.0);
    float _1799 = fast::clamp(fma(dot(-_1771, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1808 = float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1780 * _1780) / fast::max(_1766, 9.9999997473787516355514526367188e-05)) * _1799) * _1799);
    float3 _1931 = fast::normalize(_960 + _1771);
    float _1864 = fast::clamp(dot(_954, _1771), 0.0, 1.0);
    float _1868 = fast::clamp(dot(_954, _1931), 0.0, 1.0);
    float3 _1969 = cross(_954, _1931);
    float _1972 = _1868 * params.facet_alpha;
    float _1981 = params.facet_alpha / fma(_1972, _1972, dot(_1969, _1969));
    float _2027 = 1.0 - fast::clamp(dot(_1771, _1931), 0.0, 1.0);
    float _2030 = _2027 * _2027;
    float _2071 = 8192.0 * fma(-_1864, _1255, _1864 + _1255);
    float _2075 = 1.0 / (_1413 * _2071);
    float3 _2110 = (fma(facet_environment.sample(facet_environmentSmplr, _1259, level(_1397 * 4.0)).xyz, _1404 * _1367, _1390) + fast::min(fma(fma((float3(params.facet_f0) + (_1656 * ((_1648 * _1648) * _1645))) * (((_1599 * _1599) * 0.3183098733425140380859375) * (0.5 / fma(_1482, _1622, _1255 * sqrt(fma(_1482 * _1482, _1618, _1612))))), _1313, _1523), (frame.lightColor.xyz * _1482) * _1369, (_1404 * ((((fma(_1693, _1689, 2.0) * pow(fast::max(fma(-_1486, _1486, 1.0), 0.0), 0.5 * (_1693 * _1689))) * 0.15915493667125701904296875) * (_1482 * (_1693 * _1700))) * _1374)) * frame.lightColor.xyz), float3(65504.0))) + fast::min(fma(fma((float3(params.facet_f0) + (_1656 * ((_2030 * _2030) * _2027))) * (((_1981 * _1981) * 0.3183098733425140380859375) * (0.5 / fma(_1864, _1622, _1255 * sqrt(fma(_1864 * _1864, _1618, _1612))))), _1313, _1523), (_1808 * _1864) * _1369, (_1404 * ((((fma(_2075, _2071, 2.0) * pow(fast::max(fma(-_1868, _1868, 1.0), 0.0), 0.5 * (_2075 * _2071))) * 0.15915493667125701904296875) * (_1864 * (_2075 * _1700))) * _1374)) * _1808), float3(65504.0));
    float3 _2145 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2148 = dot(_2145, _2145);
    float3 _2153 = _2145 * rsqrt(fast::max(_2148, 9.9999999392252902907785028219223e-09));
    float _2157 = _2148 * float(frame.punctualLights[1].positionFalloff.w);
    float _2162 = fast::clamp(fma(-_2157, _2157, 1.0), 0.0, 1.0);
    float _2181 = fast::clamp(fma(dot(-_2153, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2190 = float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_2162 * _2162) / fast::max(_2148, 9.9999997473787516355514526367188e-05)) * _2181) * _2181);
    float3 _2313 = fast::normalize(_960 + _2153);
    float _2246 = fast::clamp(dot(_954, _2153), 0.0, 1.0);
    float _2250 = fast::clamp(dot(_954, _2313), 0.0, 1.0);
    float3 _2351 = cross(_954, _2313);
    float _2354 = _2250 * params.facet_alpha;
    float _2363 = params.facet_alpha / fma(_2354, _2354, dot(_2351, _2351));
    float _2409 = 1.0 - fast::clamp(dot(_2153, _2313), 0.0, 1.0);
    float _2412 = _2409 * _2409;
    float _2453 = 8192.0 * fma(-_2246, _1255, _2246 + _1255);
    float _2457 = 1.0 / (_1413 * _2453);
    out.fragColor = float4(_2110 + fast::min(fma(fma((float3(params.facet_f0) + (_1656 * ((_2412 * _2412) * _2409))) * (((_2363 * _2363) * 0.3183098733425140380859375) * (0.5 / fma(_2246, _1622, _1255 * sqrt(fma(_2246 * _2246, _1618, _1612))))), _1313, _1523), (_2190 * _2246) * _1369, (_1404 * ((((fma(_2457, _2453, 2.0) * pow(fast::max(fma(-_2250, _2250, 1.0), 0.0), 0.5 * (_2457 * _2453))) * 0.15915493667125701904296875) * (_2246 * (_2457 * _1700))) * _1374)) * _2190), float3(65504.0)), 1.0);
    return out;
}

