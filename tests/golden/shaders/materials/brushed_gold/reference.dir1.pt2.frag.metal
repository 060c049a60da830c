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
    float3 _756 = fast::normalize(in.v_normal);
    float3 _762 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1053 = fast::max(dot(_756, _762), 9.9999997473787516355514526367188e-05);
    float4 _1092 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1053, params.facet_perceptualRoughness), level(0.0));
    float3 _1111 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1092.y) - 1.0));
    float3 _1233 = fast::normalize(_762 + frame.lightDirection.xyz);
    float _1178 = fast::clamp(dot(_756, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1271 = cross(_756, _1233);
    float _1274 = fast::clamp(dot(_756, _1233), 0.0, 1.0) * params.facet_alpha;
    float _1283 = params.facet_alpha / fma(_1274, _1274, dot(_1271, _1271));
    float _1296 = params.facet_alpha * params.facet_alpha;
    float _1302 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1306 = sqrt(fma(_1053 * _1053, _1302, _1296));
    float _1329 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1233), 0.0, 1.0);
    float _1332 = _1329 * _1329;
    float3 _1340 = float3(1.0) - float3(params.facet_f0);
    float3 _1397 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1400 = dot(_1397, _1397);
    float3 _1405 = _1397 * rsqrt(fast::max(_1400, 9.9999999392252902907785028219223e-09));
    float _1409 = _1400 * float(frame.punctualLights[0].positionFalloff.w);
    float _1414 = fast::clamp(fma(-_1409, _1409, 1.0), 0.0, 1.0);
    float _1433 = fast::clamp(fma(dot(-_1405, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1548 = fast::normalize(_762 + _1405);
    float _1493 = fast::clamp(dot(_756, _1405), 0.0, 1.0);
    float3 _1586 = cross(_756, _1548);
    float _1589 = fast::clamp(dot(_756, _1548), 0.0, 1.0) * params.facet_alpha;
    float _1598 = params.facet_alpha / fma(_1589, _1589, dot(_1586, _1586));
    float _1644 = 1.0 - fast::clamp(dot(_1405, _1548), 0.0, 1.0);
    float _1647 = _1644 * _1644;
    float3 _1712 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1715 = dot(_1712, _1712);
    float3 _1720 = _1712 * rsqrt(fast::max(_1715, 9.9999999392252902907785028219223e-09));
    float _1724 = _1715 * float(frame.punctualLights[1].positionFalloff.w);
    float _1729 = fast::clamp(fma(-_1724, _1724, 1.0), 0.0, 1.0);
    float _1748 = fast::clamp(fma(dot(-_1720, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1863 = fast::normalize(_762 + _1720);
    float _1808 = fast::clamp(dot(_756, _1720), 0.0, 1.0);
    float3 _1901 = cross(_756, _1863);
    float _1904 = fast::clamp(dot(_756, _1863), 0.0, 1.0) * params.facet_alpha;
    float _1913 = params.facet_alpha / fma(_1904, _1904, dot(_1901, _1901));
    float _1959 = 1.0 - fast::clamp(dot(_1720, _1863), 0.0, 1.0);
    float _1962 = _1959 * _1959;
    float3 _1992 = (fma(facet_environment.sample(facet_environmentSmplr, reflect(-_762, _756), level(params.facet_perceptualRoughness * 4.0)).xyz, mix(_1092.xxx, _1092.yyy, float3(params.facet_f0)) * _1111, fast::min((((float3(params.facet_f0) + (_1340 * ((_1332 * _1332) * _1329))) * (((_1283 * _1283) * 0.3183098733425140380859375) * (0.5 / fma(_1178, _1306, _1053 * sqrt(fma(_1178 * _1178, _1302, _1296)))))) * _1111) * (frame.lightColor.xyz * _1178), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1340 * ((_1647 * _1647) * _1644))) * (((_1598 * _1598) * 0.3183098733425140380859375) * (0.5 / fma(_1493, _1306, _1053 * sqrt(fma(_1493 * _1493, _1302, _1296)))))) * _1111) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1414 * _1414) / fast::max(_1400, 9.9999997473787516355514526367188e-05)) * _1433) * _1433)) * _1493), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1340 * ((_1962 * _1962) * _1959))) * (((_1913 * _1913) * 0.3183098733425140380859375) * (0.5 / fma(_1808, _1306, _1053 * sqrt(fma(_1808 * _1808, _1302, _1296)))))) * _1111) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1729 * _1729) / fast::max(_1715, 9.9999997473787516355514526367188e-05)) * _1748) * _1748)) * _1808), float3(65504.0));
    out.fragColor = float4(_1992, 1.0);
    return out;
}

