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
    float3 _1305 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1308 = dot(_1305, _1305);
    float3 _1313 = _1305 * rsqrt(fast::max(_1308, 9.9999999392252902907785028219223e-09));
    float _1317 = _1308 * float(frame.punctualLights[0].positionFalloff.w);
    float _1322 = fast::clamp(fma(-_1317, _1317, 1.0), 0.0, 1.0);
    float _1341 = fast::clamp(fma(dot(-_1313, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1480 = _1225 * _1225;
    float _1398 = fast::clamp(dot(_855, _1313), 0.0, 1.0);
    float3 _1491 = fast::normalize(_861 + _1313);
    float _1529 = 4096.0 * _1480;
    float4 _1553 = float4(cross(_855, _1491), _1480 * fast::clamp(dot(_855, _1491), 0.0, 1.0)) * 64.0;
    float _1535 = _1529 / dot(_1553, _1553);
    float _1564 = _1480 * _1480;
    float _1570 = fma(-_1480, _1480, 1.0);
    float _1574 = sqrt(fma(_1168 * _1168, _1570, _1564));
    float _1597 = 1.0 - fast::clamp(dot(_1313, _1491), 0.0, 1.0);
    float _1600 = _1597 * _1597;
    float3 _1608 = float3(1.0) - _1216;
    float3 _1432 = _1133 * 0.3183098733425140380859375;
    float3 _1630 = fma(_1133, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1032)) + (frame.sh[2].xyz * _1037)) + (frame.sh[3].xyz * _1042)) + (((((frame.sh[4].xyz * (_1042 * _1032)) + (frame.sh[5].xyz * (_1032 * _1037))) + (frame.sh[6].xyz * fma(3.0 * _1037, _1037, -1.0))) + (frame.sh[7].xyz * (_1042 * _1037))) + (frame.sh[8].xyz * fma(_1042, _1042, -(_1032 * _1032)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_861, _855), level(_1225 * (4.0 * (2.0 - _1225)))).xyz * (mix(_1232.xxx, _1232.yyy, _1216) * _1251)) + fast::min(fma((_1216 + (_1608 * ((_1600 * _1600) * _1597))) * (((_1535 * _1535) * 0.3183098733425140380859375) * (0.5 / fma(_1398, _1574, _1168 * sqrt(fma(_1398 * _1398, _1570, _1564))))), _1251, _1432) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1322 * _1322) / fast::max(_1308, 9.9999997473787516355514526367188e-05)) * _1341) * _1341)) * _1398), float3(65504.0));
    float3 _1665 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1668 = dot(_1665, _1665);
    float3 _1673 = _1665 * rsqrt(fast::max(_1668, 9.9999999392252902907785028219223e-09));
    float _1677 = _1668 * float(frame.punctualLights[1].positionFalloff.w);
    float _1682 = fast::clamp(fma(-_1677, _1677, 1.0), 0.0, 1.0);
    float _1701 = fast::clamp(fma(dot(-_1673, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1758 = fast::clamp(dot(_855, _1673), 0.0, 1.0);
    float3 _1851 = fast::normalize(_861 + _1673);
    float4 _1913 = float4(cross(_855, _1851), _1480 * fast::clamp(dot(_855, _1851), 0.0, 1.0)) * 64.0;
    float _1895 = _1529 / dot(_1913, _1913);
    float _1957 = 1.0 - fast::clamp(dot(_1673, _1851), 0.0, 1.0);
    float _1960 = _1957 * _1957;
    out.fragColor = float4(_1630 + fast::min(fma((_1216 + (_1608 * ((_1960 * _1960) * _1957))) * (((_1895 * _1895) * 0.3183098733425140380859375) * (0.5 / fma(_1758, _1574, _1168 * sqrt(fma(_1758 * _1758, _1570, _1564))))), _1251, _1432) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1682 * _1682) / fast::max(_1668, 9.9999997473787516355514526367188e-05)) * _1701) * _1701)) * _1758), float3(65504.0)), 1.0);
    return out;
}

