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
    float _967 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _1016 = _839.y;
    float _1021 = _839.z;
    float _1026 = _839.x;
    float3 _1117 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_967)), float3(0.0), float3(1.0)) * 1.0;
    float _1192 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _967), 0.0, 1.0);
    float3 _1200 = float3((0.1599999964237213134765625 * _1192) * _1192);
    float _1209 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _967), 0.08900000154972076416015625, 1.0);
    float _1152 = fast::max(dot(_839, _845), 9.9999997473787516355514526367188e-05);
    float4 _1216 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1152, _1209), level(0.0));
    float3 _1235 = float3(1.0) + (_1200 * ((1.0 / _1216.y) - 1.0));
    float3 _1291 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1294 = dot(_1291, _1291);
    float3 _1299 = _1291 * rsqrt(fast::max(_1294, 9.9999999392252902907785028219223e-09));
    float _1303 = _1294 * float(frame.punctualLights[0].positionFalloff.w);
    float _1308 = fast::clamp(fma(-_1303, _1303, 1.0), 0.0, 1.0);
    float _1327 = fast::clamp(fma(dot(-_1299, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1466 = _1209 * _1209;
    float3 _1477 = fast::normalize(_845 + _1299);
    float _1387 = fast::clamp(dot(_839, _1299), 0.0, 1.0);
    float3 _1515 = cross(_839, _1477);
    float _1518 = fast::clamp(dot(_839, _1477), 0.0, 1.0) * _1466;
    float _1527 = _1466 / fma(_1518, _1518, dot(_1515, _1515));
    float _1540 = _1466 * _1466;
    float _1546 = fma(-_1466, _1466, 1.0);
    float _1550 = sqrt(fma(_1152 * _1152, _1546, _1540));
    float _1573 = 1.0 - fast::clamp(dot(_1299, _1477), 0.0, 1.0);
    float _1576 = _1573 * _1573;
    float3 _1584 = float3(1.0) - _1200;
    float3 _1418 = _1117 * 0.3183098733425140380859375;
    float3 _1606 = fma(_1117, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1016)) + (frame.sh[2].xyz * _1021)) + (frame.sh[3].xyz * _1026)) + (((((frame.sh[4].xyz * (_1026 * _1016)) + (frame.sh[5].xyz * (_1016 * _1021))) + (frame.sh[6].xyz * fma(3.0 * _1021, _1021, -1.0))) + (frame.sh[7].xyz * (_1026 * _1021))) + (frame.sh[8].xyz * fma(_1026, _1026, -(_1016 * _1016)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_845, _839), level(_1209 * (4.0 * (2.0 - _1209)))).xyz * (mix(_1216.xxx, _1216.yyy, _1200) * _1235)) + fast::min(fma((_1200 + (_1584 * ((_1576 * _1576) * _1573))) * (((_1527 * _1527) * 0.3183098733425140380859375) * (0.5 / fma(_1387, _1550, _1152 * sqrt(fma(_1387 * _1387, _1546, _1540))))), _1235, _1418) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1308 * _1308) / fast::max(_1294, 9.9999997473787516355514526367188e-05)) * _1327) * _1327)) * _1387), float3(65504.0));
    float3 _1641 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1644 = dot(_1641, _1641);
    float3 _1649 = _1641 * rsqrt(fast::max(_1644, 9.9999999392252902907785028219223e-09));
    float _1653 = _1644 * float(frame.punctualLights[1].positionFalloff.w);
    float _1658 = fast::clamp(fma(-_1653, _1653, 1.0), 0.0, 1.0);
    float _1677 = fast::clamp(fma(dot(-_1649, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1827 = fast::normalize(_845 + _1649);
    float _1737 = fast::clamp(dot(_839, _1649), 0.0, 1.0);
    float3 _1865 = cross(_839, _1827);
    float _1868 = fast::clamp(dot(_839, _1827), 0.0, 1.0) * _1466;
    float _1877 = _1466 / fma(_1868, _1868, dot(_1865, _1865));
    float _1923 = 1.0 - fast::clamp(dot(_1649, _1827), 0.0, 1.0);
    float _1926 = _1923 * _1923;
    out.fragColor = float4(_1606 + fast::min(fma((_1200 + (_1584 * ((_1926 * _1926) * _1923))) * (((_1877 * _1877) * 0.3183098733425140380859375) * (0.5 / fma(_1737, _1550, _1152 * sqrt(fma(_1737 * _1737, _1546, _1540))))), _1235, _1418) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1658 * _1658) / fast::max(_1644, 9.9999997473787516355514526367188e-05)) * _1677) * _1677)) * _1737), float3(65504.0)), 1.0);
    return out;
}

