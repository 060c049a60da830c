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
    float _979 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _1028 = _851.y;
    float _1033 = _851.z;
    float _1038 = _851.x;
    float3 _1129 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_979)), float3(0.0), float3(1.0)) * 1.0;
    float _1204 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _979), 0.0, 1.0);
    float3 _1212 = float3((0.1599999964237213134765625 * _1204) * _1204);
    float _1221 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _979), 0.08900000154972076416015625, 1.0);
    float _1164 = fast::max(dot(_851, _857), 9.9999997473787516355514526367188e-05);
    float4 _1228 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1164, _1221), level(0.0));
    float3 _1247 = float3(1.0) + (_1212 * ((1.0 / _1228.y) - 1.0));
    float3 _1298 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1301 = dot(_1298, _1298);
    float3 _1306 = _1298 * rsqrt(fast::max(_1301, 9.9999999392252902907785028219223e-09));
    float _1310 = _1301 * float(frame.punctualLights[0].positionFalloff.w);
    float _1315 = fast::clamp(fma(-_1310, _1310, 1.0), 0.0, 1.0);
    float _1334 = fast::clamp(fma(dot(-_1306, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1473 = _1221 * _1221;
    float3 _1484 = fast::normalize(_857 + _1306);
    float _1394 = fast::clamp(dot(_851, _1306), 0.0, 1.0);
    float _1522 = 4096.0 * _1473;
    float4 _1546 = float4(cross(_851, _1484), _1473 * fast::clamp(dot(_851, _1484), 0.0, 1.0)) * 64.0;
    float _1528 = _1522 / dot(_1546, _1546);
    float _1557 = _1473 * _1473;
    float _1563 = fma(-_1473, _1473, 1.0);
    float _1567 = sqrt(fma(_1164 * _1164, _1563, _1557));
    float _1590 = 1.0 - fast::clamp(dot(_1306, _1484), 0.0, 1.0);
    float _1593 = _1590 * _1590;
    float3 _1601 = float3(1.0) - _1212;
    float3 _1425 = _1129 * 0.3183098733425140380859375;
    float3 _1623 = fma(_1129, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1028)) + (frame.sh[2].xyz * _1033)) + (frame.sh[3].xyz * _1038)) + (((((frame.sh[4].xyz * (_1038 * _1028)) + (frame.sh[5].xyz * (_1028 * _1033))) + (frame.sh[6].xyz * fma(3.0 * _1033, _1033, -1.0))) + (frame.sh[7].xyz * (_1038 * _1033))) + (frame.sh[8].xyz * fma(_1038, _1038, -(_1028 * _1028)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_857, _851), level(_1221 * 4.0)).xyz * (mix(_1228.xxx, _1228.yyy, _1212) * _1247)) + fast::min(fma((_1212 + (_1601 * ((_1593 * _1593) * _1590))) * (((_1528 * _1528) * 0.3183098733425140380859375) * (0.5 / fma(_1394, _1567, _1164 * sqrt(fma(_1394 * _1394, _1563, _1557))))), _1247, _1425) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1315 * _1315) / fast::max(_1301, 9.9999997473787516355514526367188e-05)) * _1334) * _1334)) * _1394), float3(65504.0));
    float3 _1658 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1661 = dot(_1658, _1658);
    float3 _1666 = _1658 * rsqrt(fast::max(_1661, 9.9999999392252902907785028219223e-09));
    float _1670 = _1661 * float(frame.punctualLights[1].positionFalloff.w);
    float _1675 = fast::clamp(fma(-_1670, _1670, 1.0), 0.0, 1.0);
    float _1694 = fast::clamp(fma(dot(-_1666, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1844 = fast::normalize(_857 + _1666);
    float _1754 = fast::clamp(dot(_851, _1666), 0.0, 1.0);
    float4 _1906 = float4(cross(_851, _1844), _1473 * fast::clamp(dot(_851, _1844), 0.0, 1.0)) * 64.0;
    float _1888 = _1522 / dot(_1906, _1906);
    float _1950 = 1.0 - fast::clamp(dot(_1666, _1844), 0.0, 1.0);
    float _1953 = _1950 * _1950;
    out.fragColor = float4(_1623 + fast::min(fma((_1212 + (_1601 * ((_1953 * _1953) * _1950))) * (((_1888 * _1888) * 0.3183098733425140380859375) * (0.5 / fma(_1754, _1567, _1164 * sqrt(fma(_1754 * _1754, _1563, _1557))))), _1247, _1425) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1675 * _1675) / fast::max(_1661, 9.9999997473787516355514526367188e-05)) * _1694) * _1694)) * _1754), float3(65504.0)), 1.0);
    return out;
}

