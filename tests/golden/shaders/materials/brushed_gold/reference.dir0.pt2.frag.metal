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
    float3 _762 = fast::normalize(in.v_normal);
    float3 _768 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1035 = fast::max(dot(_762, _768), 9.9999997473787516355514526367188e-05);
    float4 _1074 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1035, params.facet_perceptualRoughness), level(0.0));
    float3 _1093 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1074.y) - 1.0));
    float3 _1149 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1152 = dot(_1149, _1149);
    float3 _1157 = _1149 * rsqrt(fast::max(_1152, 9.9999999392252902907785028219223e-09));
    float _1161 = _1152 * float(frame.punctualLights[0].positionFalloff.w);
    float _1166 = fast::clamp(fma(-_1161, _1161, 1.0), 0.0, 1.0);
    float _1185 = fast::clamp(fma(dot(-_1157, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1300 = fast::normalize(_768 + _1157);
    float _1245 = fast::clamp(dot(_762, _1157), 0.0, 1.0);
    float3 _1338 = cross(_762, _1300);
    float _1341 = fast::clamp(dot(_762, _1300), 0.0, 1.0) * params.facet_alpha;
    float _1350 = params.facet_alpha / fma(_1341, _1341, dot(_1338, _1338));
    float _1363 = params.facet_alpha * params.facet_alpha;
    float _1369 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1373 = sqrt(fma(_1035 * _1035, _1369, _1363));
    float _1396 = 1.0 - fast::clamp(dot(_1157, _1300), 0.0, 1.0);
    float _1399 = _1396 * _1396;
    float3 _1407 = float3(1.0) - float3(params.facet_f0);
    float3 _1464 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1467 = dot(_1464, _1464);
    float3 _1472 = _1464 * rsqrt(fast::max(_1467, 9.9999999392252902907785028219223e-09));
    float _1476 = _1467 * float(frame.punctualLights[1].positionFalloff.w);
    float _1481 = fast::clamp(fma(-_1476, _1476, 1.0), 0.0, 1.0);
    float _1500 = fast::clamp(fma(dot(-_1472, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1615 = fast::normalize(_768 + _1472);
    float _1560 = fast::clamp(dot(_762, _1472), 0.0, 1.0);
    float3 _1653 = cross(_762, _1615);
    float _1656 = fast::clamp(dot(_762, _1615), 0.0, 1.0) * params.facet_alpha;
    float _1665 = params.facet_alpha / fma(_1656, _1656, dot(_1653, _1653));
    float _1711 = 1.0 - fast::clamp(dot(_1472, _1615), 0.0, 1.0);
    float _1714 = _1711 * _1711;
    float3 _1744 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_768, _762), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, mix(_1074.xxx, _1074.yyy, float3(params.facet_f0)) * _1093, fast::min((((float3(params.facet_f0) + (_1407 * ((_1399 * _1399) * _1396))) * (((_1350 * _1350) * 0.3183098733425140380859375) * (0.5 / fma(_1245, _1373, _1035 * sqrt(fma(_1245 * _1245, _1369, _1363)))))) * _1093) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1166 * _1166) / fast::max(_1152, 9.9999997473787516355514526367188e-05)) * _1185) * _1185)) * _1245), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1407 * ((_1714 * _1714) * _1711))) * (((_1665 * _1665) * 0.3183098733425140380859375) * (0.5 / fma(_1560, _1373, _1035 * sqrt(fma(_1560 * _1560, _1369, _1363)))))) * _1093) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1481 * _1481) / fast::max(_1467, 9.9999997473787516355514526367188e-05)) * _1500) * _1500)) * _1560), float3(65504.0));
    out.fragColor = float4(_1744, 1.0);
    return out;
}

