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
    float3 _851 = fast::normalize(in.v_normal);
    float3 _857 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1000 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _1049 = _851.y;
    float _1054 = _851.z;
    float _1059 = _851.x;
    float3 _1150 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_1000)), float3(0.0), float3(1.0)) * 1.0;
    float _1225 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _1000), 0.0, 1.0);
    float3 _1233 = float3((0.1599999964237213134765625 * _1225) * _1225);
    float _1242 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _1000), 0.08900000154972076416015625, 1.0);
    float _1185 = fast::max(dot(_851, _857), 9.9999997473787516355514526367188e-05);
    float4 _1249 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1185, _1242), level(0.0));
    float3 _1268 = float3(1.0) + (_1233 * ((1.0 / _1249.y) - 1.0));
    float _1414 = _1242 * _1242;
    float3 _1425 = fast::normalize(_857 + frame.lightDirection.xyz);
    float _1335 = fast::clamp(dot(_851, frame.lightDirection.xyz), 0.0, 1.0);
    float _1463 = 4096.0 * _1414;
    float4 _1487 = float4(cross(_851, _1425), _1414 * fast::clamp(dot(_851, _1425), 0.0, 1.0)) * 64.0;
    float _1469 = _1463 / dot(_1487, _1487);
    float _1498 = _1414 * _1414;
    float _1504 = fma(-_1414, _1414, 1.0);
    float _1508 = sqrt(fma(_1185 * _1185, _1504, _1498));
    float _1531 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1425), 0.0, 1.0);
    float _1534 = _1531 * _1531;
    float3 _1542 = float3(1.0) - _1233;
    float3 _1366 = _1150 * 0.3183098733425140380859375;
    float3 _1564 = fma(_1150, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1049)) + (frame.sh[2].xyz * _1054)) + (frame.sh[3].xyz * _1059)) + (((((frame.sh[4].xyz * (_1059 * _1049)) + (frame.sh[5].xyz * (_1049 * _1054))) + (frame.sh[6].xyz * fma(3.0 * _1054, _1054, -1.0))) + (frame.sh[7].xyz * (_1059 * _1054))) + (frame.sh[8].xyz * fma(_1059, _1059, -(_1049 * _1049)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_857, _851), level(_1242 * 4.0)).xyz * (mix(_1249.xxx, _1249.yyy, _1233) * _1268)) + fast::min(fma((_1233 + (_1542 * ((_1534 * _1534) * _1531))) * (((_1469 * _1469) * 0.3183098733425140380859375) * (0.5 / fma(_1335, _1508, _1185 * sqrt(fma(_1335 * _1335, _1504, _1498))))), _1268, _1366) * (frame.lightColor.xyz * _1335), float3(65504.0));
    float3 _1599 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1602 = dot(_1599, _1599);
    float3 _1607 = _1599 * rsqrt(fast::max(_1602, 9.9999999392252902907785028219223e-09));
    float _1611 = _1602 * float(frame.punctualLights[0].positionFalloff.w);
    float _1616 = fast::clamp(fma(-_1611, _1611, 1.0), 0.0, 1.0);
    float _1635 = fast::clamp(fma(dot(-_1607, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1785 = fast::normalize(_857 + _1607);
    float _1695 = fast::clamp(dot(_851, _1607), 0.0, 1.0);
    float4 _1847 = float4(cross(_851, _1785), _1414 * fast::clamp(dot(_851, _1785), 0.0, 1.0)) * 64.0;
    float _1829 = _1463 / dot(_1847, _1847);
    float _1891 = 1.0 - fast::clamp(dot(_1607, _1785), 0.0, 1.0);
    float _1894 = _1891 * _1891;
    float3 _1959 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1962 = dot(_1959, _1959);
    float3 _1967 = _1959 * rsqrt(fast::max(_1962, 9.9999999392252902907785028219223e-09));
    float _1971 = _1962 * float(frame.punctualLights[1].positionFalloff.w);
    float _1976 = fast::clamp(fma(-_1971, _1971, 1.0), 0.0, 1.0);
    float _1995 = fast::clamp(fma(dot(-_1967, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2145 = fast::normalize(_857 + _1967);
    float _2055 = fast::clamp(dot(_851, _1967), 0.0, 1.0);
    float4 _2207 = float4(cross(_851, _2145), _1414 * fast::clamp(dot(_851, _2145), 0.0, 1.0)) * 64.0;
    float _2189 = _1463 / dot(_2207, _2207);
    float _2251 = 1.0 - fast::clamp(dot(_1967, _2145), 0.0, 1.0);
    float _2254 = _2251 * _2251;
    float3 _2284 = (_1564 + fast::min(fma((_1233 + (_1542 * ((_1894 * _1894) * _1891))) * (((_1829 * _1829) * 0.3183098733425140380859375) * (0.5 / fma(_1695, _1508, _1185 * sqrt(fma(_1695 * _1695, _1504, _1498))))), _1268, _1366) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1616 * _1616) / fast::max(_1602, 9.9999997473787516355514526367188e-05)) * _1635) * _1635)) * _1695), float3(65504.0))) + fast::min(fma((_1233 + (_1542 * ((_2254 * _2254) * _2251))) * (((_2189 * _2189) * 0.3183098733425140380859375) * (0.5 / fma(_2055, _1508, _1185 * sqrt(fma(_2055 * _2055, _1504, _1498))))), _1268, _1366) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1976 * _1976) / fast::max(_1962, 9.9999997473787516355514526367188e-05)) * _1995) * _1995)) * _2055), float3(65504.0));
    out.fragColor = float4(_2284, 1.0);
    return out;
}

