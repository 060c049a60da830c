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
    float _964 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _1013 = _833.y;
    float _1018 = _833.z;
    float _1023 = _833.x;
    float3 _1114 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_964)), float3(0.0), float3(1.0)) * 1.0;
    float _1189 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _964), 0.0, 1.0);
    float3 _1197 = float3((0.1599999964237213134765625 * _1189) * _1189);
    float _1206 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _964), 0.08900000154972076416015625, 1.0);
    float _1149 = fast::max(dot(_833, _839), 9.9999997473787516355514526367188e-05);
    float4 _1213 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1149, _1206), level(0.0));
    float3 _1232 = float3(1.0) + (_1197 * ((1.0 / _1213.y) - 1.0));
    float3 _1283 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1286 = dot(_1283, _1283);
    float3 _1291 = _1283 * rsqrt(fast::max(_1286, 9.9999999392252902907785028219223e-09));
    float _1295 = _1286 * float(frame.punctualLights[0].positionFalloff.w);
    float _1300 = fast::clamp(fma(-_1295, _1295, 1.0), 0.0, 1.0);
    float _1319 = fast::clamp(fma(dot(-_1291, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1458 = _1206 * _1206;
    float3 _1469 = fast::normalize(_839 + _1291);
    float _1379 = fast::clamp(dot(_833, _1291), 0.0, 1.0);
    float3 _1507 = cross(_833, _1469);
    float _1510 = fast::clamp(dot(_833, _1469), 0.0, 1.0) * _1458;
    float _1519 = _1458 / fma(_1510, _1510, dot(_1507, _1507));
    float _1532 = _1458 * _1458;
    float _1538 = fma(-_1458, _1458, 1.0);
    float _1542 = sqrt(fma(_1149 * _1149, _1538, _1532));
    float _1565 = 1.0 - fast::clamp(dot(_1291, _1469), 0.0, 1.0);
    float _1568 = _1565 * _1565;
    float3 _1576 = float3(1.0) - _1197;
    float3 _1410 = _1114 * 0.3183098733425140380859375;
    float3 _1598 = fma(_1114, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1013)) + (frame.sh[2].xyz * _1018)) + (frame.sh[3].xyz * _1023)) + (((((frame.sh[4].xyz * (_1023 * _1013)) + (frame.sh[5].xyz * (_1013 * _1018))) + (frame.sh[6].xyz * fma(3.0 * _1018, _1018, -1.0))) + (frame.sh[7].xyz * (_1023 * _1018))) + (frame.sh[8].xyz * fma(_1023, _1023, -(_1013 * _1013)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_839, _833), level(_1206 * 4.0)).xyz * (mix(_1213.xxx, _1213.yyy, _1197) * _1232)) + fast::min(fma((_1197 + (_1576 * ((_1568 * _1568) * _1565))) * (((_1519 * _1519) * 0.3183098733425140380859375) * (0.5 / fma(_1379, _1542, _1149 * sqrt(fma(_1379 * _1379, _1538, _1532))))), _1232, _1410) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1300 * _1300) / fast::max(_1286, 9.9999997473787516355514526367188e-05)) * _1319) * _1319)) * _1379), float3(65504.0));
    float3 _1633 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1636 = dot(_1633, _1633);
    float3 _1641 = _1633 * rsqrt(fast::max(_1636, 9.9999999392252902907785028219223e-09));
    float _1645 = _1636 * float(frame.punctualLights[1].positionFalloff.w);
    float _1650 = fast::clamp(fma(-_1645, _1645, 1.0), 0.0, 1.0);
    float _1669 = fast::clamp(fma(dot(-_1641, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1819 = fast::normalize(_839 + _1641);
    float _1729 = fast::clamp(dot(_833, _1641), 0.0, 1.0);
    float3 _1857 = cross(_833, _1819);
    float _1860 = fast::clamp(dot(_833, _1819), 0.0, 1.0) * _1458;
    float _1869 = _1458 / fma(_1860, _1860, dot(_1857, _1857));
    float _1915 = 1.0 - fast::clamp(dot(_1641, _1819), 0.0, 1.0);
    float _1918 = _1915 * _1915;
    out.fragColor = float4(_1598 + fast::min(fma((_1197 + (_1576 * ((_1918 * _1918) * _1915))) * (((_1869 * _1869) * 0.3183098733425140380859375) * (0.5 / fma(_1729, _1542, _1149 * sqrt(fma(_1729 * _1729, _1538, _1532))))), _1232, _1410) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1650 * _1650) / fast::max(_1636, 9.9999997473787516355514526367188e-05)) * _1669) * _1669)) * _1729), float3(65504.0)), 1.0);
    return out;
}

