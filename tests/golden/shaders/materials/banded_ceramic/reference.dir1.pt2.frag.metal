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
    float3 _855 = fast::normalize(in.v_normal);
    float3 _861 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1004 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _1053 = _855.y;
    float _1058 = _855.z;
    float _1063 = _855.x;
    float3 _1154 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_1004)), float3(0.0), float3(1.0)) * 1.0;
    float _1229 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _1004), 0.0, 1.0);
    float3 _1237 = float3((0.1599999964237213134765625 * _1229) * _1229);
    float _1246 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _1004), 0.08900000154972076416015625, 1.0);
    float _1189 = fast::max(dot(_855, _861), 9.9999997473787516355514526367188e-05);
    float4 _1253 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1189, _1246), level(0.0));
    float3 _1272 = float3(1.0) + (_1237 * ((1.0 / _1253.y) - 1.0));
    float _1421 = _1246 * _1246;
    float _1339 = fast::clamp(dot(_855, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1432 = fast::normalize(_861 + frame.lightDirection.xyz);
    float _1470 = 4096.0 * _1421;
    float4 _1494 = float4(cross(_855, _1432), _1421 * fast::clamp(dot(_855, _1432), 0.0, 1.0)) * 64.0;
    float _1476 = _1470 / dot(_1494, _1494);
    float _1505 = _1421 * _1421;
    float _1511 = fma(-_1421, _1421, 1.0);
    float _1515 = sqrt(fma(_1189 * _1189, _1511, _1505));
    float _1538 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1432), 0.0, 1.0);
    float _1541 = _1538 * _1538;
    float3 _1549 = float3(1.0) - _1237;
    float3 _1373 = _1154 * 0.3183098733425140380859375;
    float3 _1571 = fma(_1154, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1053)) + (frame.sh[2].xyz * _1058)) + (frame.sh[3].xyz * _1063)) + (((((frame.sh[4].xyz * (_1063 * _1053)) + (frame.sh[5].xyz * (_1053 * _1058))) + (frame.sh[6].xyz * fma(3.0 * _1058, _1058, -1.0))) + (frame.sh[7].xyz * (_1063 * _1058))) + (frame.sh[8].xyz * fma(_1063, _1063, -(_1053 * _1053)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_861, _855), level(_1246 * (4.0 * (2.0 - _1246)))).xyz * (mix(_1253.xxx, _1253.yyy, _1237) * _1272)) + fast::min(fma((_1237 + (_1549 * ((_1541 * _1541) * _1538))) * (((_1476 * _1476) * 0.3183098733425140380859375) * (0.5 / fma(_1339, _1515, _1189 * sqrt(fma(_1339 * _1339, _1511, _1505))))), _1272, _1373) * (frame.lightColor.xyz * _1339), float3(65504.0));
    float3 _1606 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1609 = dot(_1606, _1606);
    float3 _1614 = _1606 * rsqrt(fast::max(_1609, 9.9999999392252902907785028219223e-09));
    float _1618 = _1609 * float(frame.punctualLights[0].positionFalloff.w);
    float _1623 = fast::clamp(fma(-_1618, _1618, 1.0), 0.0, 1.0);
    float _1642 = fast::clamp(fma(dot(-_1614, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1699 = fast::clamp(dot(_855, _1614), 0.0, 1.0);
    float3 _1792 = fast::normalize(_861 + _1614);
    float4 _1854 = float4(cross(_855, _1792), _1421 * fast::clamp(dot(_855, _1792), 0.0, 1.0)) * 64.0;
    float _1836 = _1470 / dot(_1854, _1854);
    float _1898 = 1.0 - fast::clamp(dot(_1614, _1792), 0.0, 1.0);
    float _1901 = _1898 * _1898;
    float3 _1966 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1969 = dot(_1966, _1966);
    float3 _1974 = _1966 * rsqrt(fast::max(_1969, 9.9999999392252902907785028219223e-09));
    float _1978 = _1969 * float(frame.punctualLights[1].positionFalloff.w);
    float _1983 = fast::clamp(fma(-_1978, _1978, 1.0), 0.0, 1.0);
    float _2002 = fast::clamp(fma(dot(-_1974, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _2059 = fast::clamp(dot(_855, _1974), 0.0, 1.0);
    float3 _2152 = fast::normalize(_861 + _1974);
    float4 _2214 = float4(cross(_855, _2152), _1421 * fast::clamp(dot(_855, _2152), 0.0, 1.0)) * 64.0;
    float _2196 = _1470 / dot(_2214, _2214);
    float _2258 = 1.0 - fast::clamp(dot(_1974, _2152), 0.0, 1.0);
    float _2261 = _2258 * _2258;
    float3 _2291 = (_1571 + fast::min(fma((_1237 + (_1549 * ((_1901 * _1901) * _1898))) * (((_1836 * _1836) * 0.3183098733425140380859375) * (0.5 / fma(_1699, _1515, _1189 * sqrt(fma(_1699 * _1699, _1511, _1505))))), _1272, _1373) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1623 * _1623) / fast::max(_1609, 9.9999997473787516355514526367188e-05)) * _1642) * _1642)) * _1699), float3(65504.0))) + fast::min(fma((_1237 + (_1549 * ((_2261 * _2261) * _2258))) * (((_2196 * _2196) * 0.3183098733425140380859375) * (0.5 / fma(_2059, _1515, _1189 * sqrt(fma(_2059 * _2059, _1511, _1505))))), _1272, _1373) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1983 * _1983) / fast::max(_1969, 9.9999997473787516355514526367188e-05)) * _2002) * _2002)) * _2059), float3(65504.0));
    out.fragColor = float4(_2291, 1.0);
    return out;
}

