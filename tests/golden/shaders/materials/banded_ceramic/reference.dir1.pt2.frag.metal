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
    float3 _837 = fast::normalize(in.v_normal);
    float3 _843 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _986 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _1035 = _837.y;
    float _1040 = _837.z;
    float _1045 = _837.x;
    float3 _1136 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_986)), float3(0.0), float3(1.0)) * 1.0;
    float _1211 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _986), 0.0, 1.0);
    float3 _1219 = float3((0.1599999964237213134765625 * _1211) * _1211);
    float _1228 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _986), 0.08900000154972076416015625, 1.0);
    float _1171 = fast::max(dot(_837, _843), 9.9999997473787516355514526367188e-05);
    float4 _1235 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1171, _1228), level(0.0));
    float3 _1254 = float3(1.0) + (_1219 * ((1.0 / _1235.y) - 1.0));
    float _1403 = _1228 * _1228;
    float3 _1414 = fast::normalize(_843 + frame.lightDirection.xyz);
    float _1324 = fast::clamp(dot(_837, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1452 = cross(_837, _1414);
    float _1455 = fast::clamp(dot(_837, _1414), 0.0, 1.0) * _1403;
    float _1464 = _1403 / fma(_1455, _1455, dot(_1452, _1452));
    float _1477 = _1403 * _1403;
    float _1483 = fma(-_1403, _1403, 1.0);
    float _1487 = sqrt(fma(_1171 * _1171, _1483, _1477));
    float _1510 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1414), 0.0, 1.0);
    float _1513 = _1510 * _1510;
    float3 _1521 = float3(1.0) - _1219;
    float3 _1355 = _1136 * 0.3183098733425140380859375;
    float3 _1543 = fma(_1136, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1035)) + (frame.sh[2].xyz * _1040)) + (frame.sh[3].xyz * _1045)) + (((((frame.sh[4].xyz * (_1045 * _1035)) + (frame.sh[5].xyz * (_1035 * _1040))) + (frame.sh[6].xyz * fma(3.0 * _1040, _1040, -1.0))) + (frame.sh[7].xyz * (_1045 * _1040))) + (frame.sh[8].xyz * fma(_1045, _1045, -(_1035 * _1035)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_843, _837), level(_1228 * (4.0 * (2.0 - _1228)))).xyz * (mix(_1235.xxx, _1235.yyy, _1219) * _1254)) + fast::min(fma((_1219 + (_1521 * ((_1513 * _1513) * _1510))) * (((_1464 * _1464) * 0.3183098733425140380859375) * (0.5 / fma(_1324, _1487, _1171 * sqrt(fma(_1324 * _1324, _1483, _1477))))), _1254, _1355) * (frame.lightColor.xyz * _1324), float3(65504.0));
    float3 _1578 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1581 = dot(_1578, _1578);
    float3 _1586 = _1578 * rsqrt(fast::max(_1581, 9.9999999392252902907785028219223e-09));
    float _1590 = _1581 * float(frame.punctualLights[0].positionFalloff.w);
    float _1595 = fast::clamp(fma(-_1590, _1590, 1.0), 0.0, 1.0);
    float _1614 = fast::clamp(fma(dot(-_1586, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1764 = fast::normalize(_843 + _1586);
    float _1674 = fast::clamp(dot(_837, _1586), 0.0, 1.0);
    float3 _1802 = cross(_837, _1764);
    float _1805 = fast::clamp(dot(_837, _1764), 0.0, 1.0) * _1403;
    float _1814 = _1403 / fma(_1805, _1805, dot(_1802, _1802));
    float _1860 = 1.0 - fast::clamp(dot(_1586, _1764), 0.0, 1.0);
    float _1863 = _1860 * _1860;
    float3 _1928 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1931 = dot(_1928, _1928);
    float3 _1936 = _1928 * rsqrt(fast::max(_1931, 9.9999999392252902907785028219223e-09));
    float _1940 = _1931 * float(frame.punctualLights[1].positionFalloff.w);
    float _1945 = fast::clamp(fma(-_1940, _1940, 1.0), 0.0, 1.0);
    float _1964 = fast::clamp(fma(dot(-_1936, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2114 = fast::normalize(_843 + _1936);
    float _2024 = fast::clamp(dot(_837, _1936), 0.0, 1.0);
    float3 _2152 = cross(_837, _2114);
    float _2155 = fast::clamp(dot(_837, _2114), 0.0, 1.0) * _1403;
    float _2164 = _1403 / fma(_2155, _2155, dot(_2152, _2152));
    float _2210 = 1.0 - fast::clamp(dot(_1936, _2114), 0.0, 1.0);
    float _2213 = _2210 * _2210;
    float3 _2243 = (_1543 + fast::min(fma((_1219 + (_1521 * ((_1863 * _1863) * _1860))) * (((_1814 * _1814) * 0.3183098733425140380859375) * (0.5 / fma(_1674, _1487, _1171 * sqrt(fma(_1674 * _1674, _1483, _1477))))), _1254, _1355) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1595 * _1595) / fast::max(_1581, 9.9999997473787516355514526367188e-05)) * _1614) * _1614)) * _1674), float3(65504.0))) + fast::min(fma((_1219 + (_1521 * ((_2213 * _2213) * _2210))) * (((_2164 * _2164) * 0.3183098733425140380859375) * (0.5 / fma(_2024, _1487, _1171 * sqrt(fma(_2024 * _2024, _1483, _1477))))), _1254, _1355) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1945 * _1945) / fast::max(_1931, 9.9999997473787516355514526367188e-05)) * _1964) * _1964)) * _2024), float3(65504.0));
    out.fragColor = float4(_2243, 1.0);
    return out;
}

