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
    float _1418 = _1246 * _1246;
    float3 _1429 = fast::normalize(_861 + frame.lightDirection.xyz);
    float _1339 = fast::clamp(dot(_855, frame.lightDirection.xyz), 0.0, 1.0);
    float _1468 = 4096.0 * _1418;
    float3 _1487 = cross(_855, _1429) * 64.0;
    float _1490 = 64.0 * _1418;
    float _1491 = fast::clamp(dot(_855, _1429), 0.0, 1.0) * _1490;
    float _1474 = _1468 / fma(_1491, _1491, dot(_1487, _1487));
    float _1506 = _1418 * _1418;
    float _1512 = fma(-_1418, _1418, 1.0);
    float _1516 = sqrt(fma(_1189 * _1189, _1512, _1506));
    float _1539 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1429), 0.0, 1.0);
    float _1542 = _1539 * _1539;
    float3 _1550 = float3(1.0) - _1237;
    float3 _1370 = _1154 * 0.3183098733425140380859375;
    float3 _1572 = fma(_1154, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1053)) + (frame.sh[2].xyz * _1058)) + (frame.sh[3].xyz * _1063)) + (((((frame.sh[4].xyz * (_1063 * _1053)) + (frame.sh[5].xyz * (_1053 * _1058))) + (frame.sh[6].xyz * fma(3.0 * _1058, _1058, -1.0))) + (frame.sh[7].xyz * (_1063 * _1058))) + (frame.sh[8].xyz * fma(_1063, _1063, -(_1053 * _1053)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_861, _855), level(_1246 * 4.0)).xyz * (mix(_1253.xxx, _1253.yyy, _1237) * _1272)) + fast::min(fma((_1237 + (_1550 * ((_1542 * _1542) * _1539))) * (((_1474 * _1474) * 0.3183098733425140380859375) * (0.5 / fma(_1339, _1516, _1189 * sqrt(fma(_1339 * _1339, _1512, _1506))))), _1272, _1370) * (frame.lightColor.xyz * _1339), float3(65504.0));
    float3 _1607 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1610 = dot(_1607, _1607);
    float3 _1615 = _1607 * rsqrt(fast::max(_1610, 9.9999999392252902907785028219223e-09));
    float _1619 = _1610 * float(frame.punctualLights[0].positionFalloff.w);
    float _1624 = fast::clamp(fma(-_1619, _1619, 1.0), 0.0, 1.0);
    float _1643 = fast::clamp(fma(dot(-_1615, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1793 = fast::normalize(_861 + _1615);
    float _1703 = fast::clamp(dot(_855, _1615), 0.0, 1.0);
    float3 _1851 = cross(_855, _1793) * 64.0;
    float _1855 = fast::clamp(dot(_855, _1793), 0.0, 1.0) * _1490;
    float _1838 = _1468 / fma(_1855, _1855, dot(_1851, _1851));
    float _1903 = 1.0 - fast::clamp(dot(_1615, _1793), 0.0, 1.0);
    float _1906 = _1903 * _1903;
    float3 _1971 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1974 = dot(_1971, _1971);
    float3 _1979 = _1971 * rsqrt(fast::max(_1974, 9.9999999392252902907785028219223e-09));
    float _1983 = _1974 * float(frame.punctualLights[1].positionFalloff.w);
    float _1988 = fast::clamp(fma(-_1983, _1983, 1.0), 0.0, 1.0);
    float _2007 = fast::clamp(fma(dot(-_1979, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2157 = fast::normalize(_861 + _1979);
    float _2067 = fast::clamp(dot(_855, _1979), 0.0, 1.0);
    float3 _2215 = cross(_855, _2157) * 64.0;
    float _2219 = fast::clamp(dot(_855, _2157), 0.0, 1.0) * _1490;
    float _2202 = _1468 / fma(_2219, _2219, dot(_2215, _2215));
    float _2267 = 1.0 - fast::clamp(dot(_1979, _2157), 0.0, 1.0);
    float _2270 = _2267 * _2267;
    float3 _2300 = (_1572 + fast::min(fma((_1237 + (_1550 * ((_1906 * _1906) * _1903))) * (((_1838 * _1838) * 0.3183098733425140380859375) * (0.5 / fma(_1703, _1516, _1189 * sqrt(fma(_1703 * _1703, _1512, _1506))))), _1272, _1370) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1624 * _1624) / fast::max(_1610, 9.9999997473787516355514526367188e-05)) * _1643) * _1643)) * _1703), float3(65504.0))) + fast::min(fma((_1237 + (_1550 * ((_2270 * _2270) * _2267))) * (((_2202 * _2202) * 0.3183098733425140380859375) * (0.5 / fma(_2067, _1516, _1189 * sqrt(fma(_2067 * _2067, _1512, _1506))))), _1272, _1370) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1988 * _1988) / fast::max(_1974, 9.9999997473787516355514526367188e-05)) * _2007) * _2007)) * _2067), float3(65504.0));
    out.fragColor = float4(_2300, 1.0);
    return out;
}

