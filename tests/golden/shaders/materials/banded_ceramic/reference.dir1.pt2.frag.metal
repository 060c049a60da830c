#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 glazeColor;
    packed_float3 clayColor;
    float glazeRoughness;
    float clayRoughness;
    float bandsPerUnit;
    float bandSharpness;
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
    float3 _839 = fast::normalize(in.v_normal);
    float3 _845 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _988 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _1037 = _839.y;
    float _1042 = _839.z;
    float _1047 = _839.x;
    float3 _1138 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_988)), float3(0.0), float3(1.0)) * 1.0;
    float _1213 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _988), 0.0, 1.0);
    float3 _1221 = float3((0.1599999964237213134765625 * _1213) * _1213);
    float _1230 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _988), 0.08900000154972076416015625, 1.0);
    float _1173 = fast::max(dot(_839, _845), 9.9999997473787516355514526367188e-05);
    float4 _1237 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1173, _1230), level(0.0));
    float3 _1256 = float3(1.0) + (_1221 * ((1.0 / _1237.y) - 1.0));
    float _1407 = _1230 * _1230;
    float3 _1418 = fast::normalize(_845 + frame.lightDirection.xyz);
    float _1328 = fast::clamp(dot(_839, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1456 = cross(_839, _1418);
    float _1459 = fast::clamp(dot(_839, _1418), 0.0, 1.0) * _1407;
    float _1468 = _1407 / fma(_1459, _1459, dot(_1456, _1456));
    float _1481 = _1407 * _1407;
    float _1487 = fma(-_1407, _1407, 1.0);
    float _1491 = sqrt(fma(_1173 * _1173, _1487, _1481));
    float _1514 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1418), 0.0, 1.0);
    float _1517 = _1514 * _1514;
    float3 _1525 = float3(1.0) - _1221;
    float3 _1359 = _1138 * 0.3183098733425140380859375;
    float3 _1547 = fma(_1138, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1037)) + (frame.sh[2].xyz * _1042)) + (frame.sh[3].xyz * _1047)) + (((((frame.sh[4].xyz * (_1047 * _1037)) + (frame.sh[5].xyz * (_1037 * _1042))) + (frame.sh[6].xyz * fma(3.0 * _1042, _1042, -1.0))) + (frame.sh[7].xyz * (_1047 * _1042))) + (frame.sh[8].xyz * fma(_1047, _1047, -(_1037 * _1037)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_845, _839), level(_1230 * (4.0 * (2.0 - _1230)))).xyz * (mix(_1237.xxx, _1237.yyy, _1221) * _1256)) + fast::min(fma((_1221 + (_1525 * ((_1517 * _1517) * _1514))) * (((_1468 * _1468) * 0.3183098733425140380859375) * (0.5 / fma(_1328, _1491, _1173 * sqrt(fma(_1328 * _1328, _1487, _1481))))), _1256, _1359) * (frame.lightColor.xyz * _1328), float3(65504.0));
    float3 _1582 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1585 = dot(_1582, _1582);
    float3 _1590 = _1582 * rsqrt(fast::max(_1585, 9.9999999392252902907785028219223e-09));
    float _1594 = _1585 * float(frame.punctualLights[0].positionFalloff.w);
    float _1599 = fast::clamp(fma(-_1594, _1594, 1.0), 0.0, 1.0);
    float _1618 = fast::clamp(fma(dot(-_1590, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1768 = fast::normalize(_845 + _1590);
    float _1678 = fast::clamp(dot(_839, _1590), 0.0, 1.0);
    float3 _1806 = cross(_839, _1768);
    float _1809 = fast::clamp(dot(_839, _1768), 0.0, 1.0) * _1407;
    float _1818 = _1407 / fma(_1809, _1809, dot(_1806, _1806));
    float _1864 = 1.0 - fast::clamp(dot(_1590, _1768), 0.0, 1.0);
    float _1867 = _1864 * _1864;
    float3 _1932 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1935 = dot(_1932, _1932);
    float3 _1940 = _1932 * rsqrt(fast::max(_1935, 9.9999999392252902907785028219223e-09));
    float _1944 = _1935 * float(frame.punctualLights[1].positionFalloff.w);
    float _1949 = fast::clamp(fma(-_1944, _1944, 1.0), 0.0, 1.0);
    float _1968 = fast::clamp(fma(dot(-_1940, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2118 = fast::normalize(_845 + _1940);
    float _2028 = fast::clamp(dot(_839, _1940), 0.0, 1.0);
    float3 _2156 = cross(_839, _2118);
    float _2159 = fast::clamp(dot(_839, _2118), 0.0, 1.0) * _1407;
    float _2168 = _1407 / fma(_2159, _2159, dot(_2156, _2156));
    float _2214 = 1.0 - fast::clamp(dot(_1940, _2118), 0.0, 1.0);
    float _2217 = _2214 * _2214;
    float3 _2247 = (_1547 + fast::min(fma((_1221 + (_1525 * ((_1867 * _1867) * _1864))) * (((_1818 * _1818) * 0.3183098733425140380859375) * (0.5 / fma(_1678, _1491, _1173 * sqrt(fma(_1678 * _1678, _1487, _1481))))), _1256, _1359) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1599 * _1599) / fast::max(_1585, 9.9999997473787516355514526367188e-05)) * _1618) * _1618)) * _1678), float3(65504.0))) + fast::min(fma((_1221 + (_1525 * ((_2217 * _2217) * _2214))) * (((_2168 * _2168) * 0.3183098733425140380859375) * (0.5 / fma(_2028, _1491, _1173 * sqrt(fma(_2028 * _2028, _1487, _1481))))), _1256, _1359) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1949 * _1949) / fast::max(_1935, 9.9999997473787516355514526367188e-05)) * _1968) * _1968)) * _2028), float3(65504.0));
    out.fragColor = float4(_2247, 1.0);
    return out;
}

