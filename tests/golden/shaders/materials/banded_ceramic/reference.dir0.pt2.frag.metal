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
    float _961 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _1010 = _833.y;
    float _1015 = _833.z;
    float _1020 = _833.x;
    float3 _1111 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_961)), float3(0.0), float3(1.0)) * 1.0;
    float _1186 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _961), 0.0, 1.0);
    float3 _1194 = float3((0.1599999964237213134765625 * _1186) * _1186);
    float _1203 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _961), 0.08900000154972076416015625, 1.0);
    float _1146 = fast::max(dot(_833, _839), 9.9999997473787516355514526367188e-05);
    float4 _1210 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1146, _1203), level(0.0));
    float3 _1229 = float3(1.0) + (_1194 * ((1.0 / _1210.y) - 1.0));
    float3 _1280 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1283 = dot(_1280, _1280);
    float3 _1288 = _1280 * rsqrt(fast::max(_1283, 9.9999999392252902907785028219223e-09));
    float _1292 = _1283 * float(frame.punctualLights[0].positionFalloff.w);
    float _1297 = fast::clamp(fma(-_1292, _1292, 1.0), 0.0, 1.0);
    float _1316 = fast::clamp(fma(dot(-_1288, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1455 = _1203 * _1203;
    float3 _1466 = fast::normalize(_839 + _1288);
    float _1376 = fast::clamp(dot(_833, _1288), 0.0, 1.0);
    float3 _1504 = cross(_833, _1466);
    float _1507 = fast::clamp(dot(_833, _1466), 0.0, 1.0) * _1455;
    float _1516 = _1455 / fma(_1507, _1507, dot(_1504, _1504));
    float _1529 = _1455 * _1455;
    float _1535 = fma(-_1455, _1455, 1.0);
    float _1539 = sqrt(fma(_1146 * _1146, _1535, _1529));
    float _1562 = 1.0 - fast::clamp(dot(_1288, _1466), 0.0, 1.0);
    float _1565 = _1562 * _1562;
    float3 _1573 = float3(1.0) - _1194;
    float3 _1407 = _1111 * 0.3183098733425140380859375;
    float3 _1595 = fma(_1111, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1010)) + (frame.sh[2].xyz * _1015)) + (frame.sh[3].xyz * _1020)) + (((((frame.sh[4].xyz * (_1020 * _1010)) + (frame.sh[5].xyz * (_1010 * _1015))) + (frame.sh[6].xyz * fma(3.0 * _1015, _1015, -1.0))) + (frame.sh[7].xyz * (_1020 * _1015))) + (frame.sh[8].xyz * fma(_1020, _1020, -(_1010 * _1010)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_839, _833), level(_1203 * 4.0)).xyz * (mix(_1210.xxx, _1210.yyy, _1194) * _1229)) + fast::min(fma((_1194 + (_1573 * ((_1565 * _1565) * _1562))) * (((_1516 * _1516) * 0.3183098733425140380859375) * (0.5 / fma(_1376, _1539, _1146 * sqrt(fma(_1376 * _1376, _1535, _1529))))), _1229, _1407) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1297 * _1297) / fast::max(_1283, 9.9999997473787516355514526367188e-05)) * _1316) * _1316)) * _1376), float3(65504.0));
    float3 _1630 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1633 = dot(_1630, _1630);
    float3 _1638 = _1630 * rsqrt(fast::max(_1633, 9.9999999392252902907785028219223e-09));
    float _1642 = _1633 * float(frame.punctualLights[1].positionFalloff.w);
    float _1647 = fast::clamp(fma(-_1642, _1642, 1.0), 0.0, 1.0);
    float _1666 = fast::clamp(fma(dot(-_1638, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1816 = fast::normalize(_839 + _1638);
    float _1726 = fast::clamp(dot(_833, _1638), 0.0, 1.0);
    float3 _1854 = cross(_833, _1816);
    float _1857 = fast::clamp(dot(_833, _1816), 0.0, 1.0) * _1455;
    float _1866 = _1455 / fma(_1857, _1857, dot(_1854, _1854));
    float _1912 = 1.0 - fast::clamp(dot(_1638, _1816), 0.0, 1.0);
    float _1915 = _1912 * _1912;
    out.fragColor = float4(_1595 + fast::min(fma((_1194 + (_1573 * ((_1915 * _1915) * _1912))) * (((_1866 * _1866) * 0.3183098733425140380859375) * (0.5 / fma(_1726, _1539, _1146 * sqrt(fma(_1726 * _1726, _1535, _1529))))), _1229, _1407) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1647 * _1647) / fast::max(_1633, 9.9999997473787516355514526367188e-05)) * _1666) * _1666)) * _1726), float3(65504.0)), 1.0);
    return out;
}

