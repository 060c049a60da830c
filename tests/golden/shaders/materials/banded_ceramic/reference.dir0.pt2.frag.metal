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
    float _965 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _1014 = _837.y;
    float _1019 = _837.z;
    float _1024 = _837.x;
    float3 _1115 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_965)), float3(0.0), float3(1.0)) * 1.0;
    float _1190 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _965), 0.0, 1.0);
    float3 _1198 = float3((0.1599999964237213134765625 * _1190) * _1190);
    float _1207 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _965), 0.08900000154972076416015625, 1.0);
    float _1150 = fast::max(dot(_837, _843), 9.9999997473787516355514526367188e-05);
    float4 _1214 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1150, _1207), level(0.0));
    float3 _1233 = float3(1.0) + (_1198 * ((1.0 / _1214.y) - 1.0));
    float3 _1287 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1290 = dot(_1287, _1287);
    float3 _1295 = _1287 * rsqrt(fast::max(_1290, 9.9999999392252902907785028219223e-09));
    float _1299 = _1290 * float(frame.punctualLights[0].positionFalloff.w);
    float _1304 = fast::clamp(fma(-_1299, _1299, 1.0), 0.0, 1.0);
    float _1323 = fast::clamp(fma(dot(-_1295, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1462 = _1207 * _1207;
    float3 _1473 = fast::normalize(_843 + _1295);
    float _1383 = fast::clamp(dot(_837, _1295), 0.0, 1.0);
    float3 _1511 = cross(_837, _1473);
    float _1514 = fast::clamp(dot(_837, _1473), 0.0, 1.0) * _1462;
    float _1523 = _1462 / fma(_1514, _1514, dot(_1511, _1511));
    float _1536 = _1462 * _1462;
    float _1542 = fma(-_1462, _1462, 1.0);
    float _1546 = sqrt(fma(_1150 * _1150, _1542, _1536));
    float _1569 = 1.0 - fast::clamp(dot(_1295, _1473), 0.0, 1.0);
    float _1572 = _1569 * _1569;
    float3 _1580 = float3(1.0) - _1198;
    float3 _1414 = _1115 * 0.3183098733425140380859375;
    float3 _1602 = fma(_1115, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1014)) + (frame.sh[2].xyz * _1019)) + (frame.sh[3].xyz * _1024)) + (((((frame.sh[4].xyz * (_1024 * _1014)) + (frame.sh[5].xyz * (_1014 * _1019))) + (frame.sh[6].xyz * fma(3.0 * _1019, _1019, -1.0))) + (frame.sh[7].xyz * (_1024 * _1019))) + (frame.sh[8].xyz * fma(_1024, _1024, -(_1014 * _1014)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_843, _837), level(_1207 * (4.0 * (2.0 - _1207)))).xyz * (mix(_1214.xxx, _1214.yyy, _1198) * _1233)) + fast::min(fma((_1198 + (_1580 * ((_1572 * _1572) * _1569))) * (((_1523 * _1523) * 0.3183098733425140380859375) * (0.5 / fma(_1383, _1546, _1150 * sqrt(fma(_1383 * _1383, _1542, _1536))))), _1233, _1414) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1304 * _1304) / fast::max(_1290, 9.9999997473787516355514526367188e-05)) * _1323) * _1323)) * _1383), float3(65504.0));
    float3 _1637 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1640 = dot(_1637, _1637);
    float3 _1645 = _1637 * rsqrt(fast::max(_1640, 9.9999999392252902907785028219223e-09));
    float _1649 = _1640 * float(frame.punctualLights[1].positionFalloff.w);
    float _1654 = fast::clamp(fma(-_1649, _1649, 1.0), 0.0, 1.0);
    float _1673 = fast::clamp(fma(dot(-_1645, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1823 = fast::normalize(_843 + _1645);
    float _1733 = fast::clamp(dot(_837, _1645), 0.0, 1.0);
    float3 _1861 = cross(_837, _1823);
    float _1864 = fast::clamp(dot(_837, _1823), 0.0, 1.0) * _1462;
    float _1873 = _1462 / fma(_1864, _1864, dot(_1861, _1861));
    float _1919 = 1.0 - fast::clamp(dot(_1645, _1823), 0.0, 1.0);
    float _1922 = _1919 * _1919;
    out.fragColor = float4(_1602 + fast::min(fma((_1198 + (_1580 * ((_1922 * _1922) * _1919))) * (((_1873 * _1873) * 0.3183098733425140380859375) * (0.5 / fma(_1733, _1546, _1150 * sqrt(fma(_1733 * _1733, _1542, _1536))))), _1233, _1414) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1654 * _1654) / fast::max(_1640, 9.9999997473787516355514526367188e-05)) * _1673) * _1673)) * _1733), float3(65504.0)), 1.0);
    return out;
}

