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
    float3 _833 = fast::normalize(in.v_normal);
    float3 _839 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _985 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _1034 = _833.y;
    float _1039 = _833.z;
    float _1044 = _833.x;
    float3 _1135 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_985)), float3(0.0), float3(1.0)) * 1.0;
    float _1210 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _985), 0.0, 1.0);
    float3 _1218 = float3((0.1599999964237213134765625 * _1210) * _1210);
    float _1227 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _985), 0.08900000154972076416015625, 1.0);
    float _1170 = fast::max(dot(_833, _839), 9.9999997473787516355514526367188e-05);
    float4 _1234 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1170, _1227), level(0.0));
    float3 _1253 = float3(1.0) + (_1218 * ((1.0 / _1234.y) - 1.0));
    float _1399 = _1227 * _1227;
    float3 _1410 = fast::normalize(_839 + frame.lightDirection.xyz);
    float _1320 = fast::clamp(dot(_833, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1448 = cross(_833, _1410);
    float _1451 = fast::clamp(dot(_833, _1410), 0.0, 1.0) * _1399;
    float _1460 = _1399 / fma(_1451, _1451, dot(_1448, _1448));
    float _1473 = _1399 * _1399;
    float _1479 = fma(-_1399, _1399, 1.0);
    float _1483 = sqrt(fma(_1170 * _1170, _1479, _1473));
    float _1506 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1410), 0.0, 1.0);
    float _1509 = _1506 * _1506;
    float3 _1517 = float3(1.0) - _1218;
    float3 _1351 = _1135 * 0.3183098733425140380859375;
    float3 _1539 = fma(_1135, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1034)) + (frame.sh[2].xyz * _1039)) + (frame.sh[3].xyz * _1044)) + (((((frame.sh[4].xyz * (_1044 * _1034)) + (frame.sh[5].xyz * (_1034 * _1039))) + (frame.sh[6].xyz * fma(3.0 * _1039, _1039, -1.0))) + (frame.sh[7].xyz * (_1044 * _1039))) + (frame.sh[8].xyz * fma(_1044, _1044, -(_1034 * _1034)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_839, _833), level(_1227 * 4.0)).xyz * (mix(_1234.xxx, _1234.yyy, _1218) * _1253)) + fast::min(fma((_1218 + (_1517 * ((_1509 * _1509) * _1506))) * (((_1460 * _1460) * 0.3183098733425140380859375) * (0.5 / fma(_1320, _1483, _1170 * sqrt(fma(_1320 * _1320, _1479, _1473))))), _1253, _1351) * (frame.lightColor.xyz * _1320), float3(65504.0));
    float3 _1574 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1577 = dot(_1574, _1574);
    float3 _1582 = _1574 * rsqrt(fast::max(_1577, 9.9999999392252902907785028219223e-09));
    float _1586 = _1577 * float(frame.punctualLights[0].positionFalloff.w);
    float _1591 = fast::clamp(fma(-_1586, _1586, 1.0), 0.0, 1.0);
    float _1610 = fast::clamp(fma(dot(-_1582, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1760 = fast::normalize(_839 + _1582);
    float _1670 = fast::clamp(dot(_833, _1582), 0.0, 1.0);
    float3 _1798 = cross(_833, _1760);
    float _1801 = fast::clamp(dot(_833, _1760), 0.0, 1.0) * _1399;
    float _1810 = _1399 / fma(_1801, _1801, dot(_1798, _1798));
    float _1856 = 1.0 - fast::clamp(dot(_1582, _1760), 0.0, 1.0);
    float _1859 = _1856 * _1856;
    float3 _1924 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1927 = dot(_1924, _1924);
    float3 _1932 = _1924 * rsqrt(fast::max(_1927, 9.9999999392252902907785028219223e-09));
    float _1936 = _1927 * float(frame.punctualLights[1].positionFalloff.w);
    float _1941 = fast::clamp(fma(-_1936, _1936, 1.0), 0.0, 1.0);
    float _1960 = fast::clamp(fma(dot(-_1932, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2110 = fast::normalize(_839 + _1932);
    float _2020 = fast::clamp(dot(_833, _1932), 0.0, 1.0);
    float3 _2148 = cross(_833, _2110);
    float _2151 = fast::clamp(dot(_833, _2110), 0.0, 1.0) * _1399;
    float _2160 = _1399 / fma(_2151, _2151, dot(_2148, _2148));
    float _2206 = 1.0 - fast::clamp(dot(_1932, _2110), 0.0, 1.0);
    float _2209 = _2206 * _2206;
    float3 _2239 = (_1539 + fast::min(fma((_1218 + (_1517 * ((_1859 * _1859) * _1856))) * (((_1810 * _1810) * 0.3183098733425140380859375) * (0.5 / fma(_1670, _1483, _1170 * sqrt(fma(_1670 * _1670, _1479, _1473))))), _1253, _1351) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1591 * _1591) / fast::max(_1577, 9.9999997473787516355514526367188e-05)) * _1610) * _1610)) * _1670), float3(65504.0))) + fast::min(fma((_1218 + (_1517 * ((_2209 * _2209) * _2206))) * (((_2160 * _2160) * 0.3183098733425140380859375) * (0.5 / fma(_2020, _1483, _1170 * sqrt(fma(_2020 * _2020, _1479, _1473))))), _1253, _1351) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1941 * _1941) / fast::max(_1927, 9.9999997473787516355514526367188e-05)) * _1960) * _1960)) * _2020), float3(65504.0));
    out.fragColor = float4(_2239, 1.0);
    return out;
}

