#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float facet_perceptualRoughness;
    char _m3_pad[12];
    packed_float3 facet_f0;
    float facet_alpha;
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
    float3 _760 = fast::normalize(in.v_normal);
    float3 _766 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1054 = fast::max(dot(_760, _766), 9.9999997473787516355514526367188e-05);
    float4 _1093 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1054, params.facet_perceptualRoughness), level(0.0));
    float3 _1112 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1093.y) - 1.0));
    float3 _1237 = fast::normalize(_766 + frame.lightDirection.xyz);
    float _1182 = fast::clamp(dot(_760, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1275 = cross(_760, _1237);
    float _1278 = fast::clamp(dot(_760, _1237), 0.0, 1.0) * params.facet_alpha;
    float _1287 = params.facet_alpha / fma(_1278, _1278, dot(_1275, _1275));
    float _1300 = params.facet_alpha * params.facet_alpha;
    float _1306 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1310 = sqrt(fma(_1054 * _1054, _1306, _1300));
    float _1333 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1237), 0.0, 1.0);
    float _1336 = _1333 * _1333;
    float3 _1344 = float3(1.0) - float3(params.facet_f0);
    float3 _1401 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1404 = dot(_1401, _1401);
    float3 _1409 = _1401 * rsqrt(fast::max(_1404, 9.9999999392252902907785028219223e-09));
    float _1413 = _1404 * float(frame.punctualLights[0].positionFalloff.w);
    float _1418 = fast::clamp(fma(-_1413, _1413, 1.0), 0.0, 1.0);
    float _1437 = fast::clamp(fma(dot(-_1409, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1552 = fast::normalize(_766 + _1409);
    float _1497 = fast::clamp(dot(_760, _1409), 0.0, 1.0);
    float3 _1590 = cross(_760, _1552);
    float _1593 = fast::clamp(dot(_760, _1552), 0.0, 1.0) * params.facet_alpha;
    float _1602 = params.facet_alpha / fma(_1593, _1593, dot(_1590, _1590));
    float _1648 = 1.0 - fast::clamp(dot(_1409, _1552), 0.0, 1.0);
    float _1651 = _1648 * _1648;
    float3 _1716 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1719 = dot(_1716, _1716);
    float3 _1724 = _1716 * rsqrt(fast::max(_1719, 9.9999999392252902907785028219223e-09));
    float _1728 = _1719 * float(frame.punctualLights[1].positionFalloff.w);
    float _1733 = fast::clamp(fma(-_1728, _1728, 1.0), 0.0, 1.0);
    float _1752 = fast::clamp(fma(dot(-_1724, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1867 = fast::normalize(_766 + _1724);
    float _1812 = fast::clamp(dot(_760, _1724), 0.0, 1.0);
    float3 _1905 = cross(_760, _1867);
    float _1908 = fast::clamp(dot(_760, _1867), 0.0, 1.0) * params.facet_alpha;
    float _1917 = params.facet_alpha / fma(_1908, _1908, dot(_1905, _1905));
    float _1963 = 1.0 - fast::clamp(dot(_1724, _1867), 0.0, 1.0);
    float _1966 = _1963 * _1963;
    float3 _1996 = (fma(facet_environment.sample(facet_environmentSmplr, reflect(-_766, _760), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, mix(_1093.xxx, _1093.yyy, float3(params.facet_f0)) * _1112, fast::min((((float3(params.facet_f0) + (_1344 * ((_1336 * _1336) * _1333))) * (((_1287 * _1287) * 0.3183098733425140380859375) * (0.5 / fma(_1182, _1310, _1054 * sqrt(fma(_1182 * _1182, _1306, _1300)))))) * _1112) * (frame.lightColor.xyz * _1182), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1344 * ((_1651 * _1651) * _1648))) * (((_1602 * _1602) * 0.3183098733425140380859375) * (0.5 / fma(_1497, _1310, _1054 * sqrt(fma(_1497 * _1497, _1306, _1300)))))) * _1112) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1418 * _1418) / fast::max(_1404, 9.9999997473787516355514526367188e-05)) * _1437) * _1437)) * _1497), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1344 * ((_1966 * _1966) * _1963))) * (((_1917 * _1917) * 0.3183098733425140380859375) * (0.5 / fma(_1812, _1310, _1054 * sqrt(fma(_1812 * _1812, _1306, _1300)))))) * _1112) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1733 * _1733) / fast::max(_1719, 9.9999997473787516355514526367188e-05)) * _1752) * _1752)) * _1812), float3(65504.0));
    out.fragColor = float4(_1996, 1.0);
    return out;
}

