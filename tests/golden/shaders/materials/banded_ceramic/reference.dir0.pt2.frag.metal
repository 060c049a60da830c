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
    float _983 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _1032 = _855.y;
    float _1037 = _855.z;
    float _1042 = _855.x;
    float3 _1133 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_983)), float3(0.0), float3(1.0)) * 1.0;
    float _1208 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _983), 0.0, 1.0);
    float3 _1216 = float3((0.1599999964237213134765625 * _1208) * _1208);
    float _1225 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _983), 0.08900000154972076416015625, 1.0);
    float _1168 = fast::max(dot(_855, _861), 9.9999997473787516355514526367188e-05);
    float4 _1232 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1168, _1225), level(0.0));
    float3 _1251 = float3(1.0) + (_1216 * ((1.0 / _1232.y) - 1.0));
    float3 _1302 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1305 = dot(_1302, _1302);
    float3 _1310 = _1302 * rsqrt(fast::max(_1305, 9.9999999392252902907785028219223e-09));
    float _1314 = _1305 * float(frame.punctualLights[0].positionFalloff.w);
    float _1319 = fast::clamp(fma(-_1314, _1314, 1.0), 0.0, 1.0);
    float _1338 = fast::clamp(fma(dot(-_1310, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1477 = _1225 * _1225;
    float3 _1488 = fast::normalize(_861 + _1310);
    float _1398 = fast::clamp(dot(_855, _1310), 0.0, 1.0);
    float _1527 = 4096.0 * _1477;
    float3 _1546 = cross(_855, _1488) * 64.0;
    float _1549 = 64.0 * _1477;
    float _1550 = fast::clamp(dot(_855, _1488), 0.0, 1.0) * _1549;
    float _1533 = _1527 / fma(_1550, _1550, dot(_1546, _1546));
    float _1565 = _1477 * _1477;
    float _1571 = fma(-_1477, _1477, 1.0);
    float _1575 = sqrt(fma(_1168 * _1168, _1571, _1565));
    float _1598 = 1.0 - fast::clamp(dot(_1310, _1488), 0.0, 1.0);
    float _1601 = _1598 * _1598;
    float3 _1609 = float3(1.0) - _1216;
    float3 _1429 = _1133 * 0.3183098733425140380859375;
    float3 _1631 = fma(_1133, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1032)) + (frame.sh[2].xyz * _1037)) + (frame.sh[3].xyz * _1042)) + (((((frame.sh[4].xyz * (_1042 * _1032)) + (frame.sh[5].xyz * (_1032 * _1037))) + (frame.sh[6].xyz * fma(3.0 * _1037, _1037, -1.0))) + (frame.sh[7].xyz * (_1042 * _1037))) + (frame.sh[8].xyz * fma(_1042, _1042, -(_1032 * _1032)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_861, _855), level(_1225 * 4.0)).xyz * (mix(_1232.xxx, _1232.yyy, _1216) * _1251)) + fast::min(fma((_1216 + (_1609 * ((_1601 * _1601) * _1598))) * (((_1533 * _1533) * 0.3183098733425140380859375) * (0.5 / fma(_1398, _1575, _1168 * sqrt(fma(_1398 * _1398, _1571, _1565))))), _1251, _1429) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1319 * _1319) / fast::max(_1305, 9.9999997473787516355514526367188e-05)) * _1338) * _1338)) * _1398), float3(65504.0));
    float3 _1666 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1669 = dot(_1666, _1666);
    float3 _1674 = _1666 * rsqrt(fast::max(_1669, 9.9999999392252902907785028219223e-09));
    float _1678 = _1669 * float(frame.punctualLights[1].positionFalloff.w);
    float _1683 = fast::clamp(fma(-_1678, _1678, 1.0), 0.0, 1.0);
    float _1702 = fast::clamp(fma(dot(-_1674, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1852 = fast::normalize(_861 + _1674);
    float _1762 = fast::clamp(dot(_855, _1674), 0.0, 1.0);
    float3 _1910 = cross(_855, _1852) * 64.0;
    float _1914 = fast::clamp(dot(_855, _1852), 0.0, 1.0) * _1549;
    float _1897 = _1527 / fma(_1914, _1914, dot(_1910, _1910));
    float _1962 = 1.0 - fast::clamp(dot(_1674, _1852), 0.0, 1.0);
    float _1965 = _1962 * _1962;
    out.fragColor = float4(_1631 + fast::min(fma((_1216 + (_1609 * ((_1965 * _1965) * _1962))) * (((_1897 * _1897) * 0.3183098733425140380859375) * (0.5 / fma(_1762, _1575, _1168 * sqrt(fma(_1762 * _1762, _1571, _1565))))), _1251, _1429) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1683 * _1683) / fast::max(_1669, 9.9999997473787516355514526367188e-05)) * _1702) * _1702)) * _1762), float3(65504.0)), 1.0);
    return out;
}

