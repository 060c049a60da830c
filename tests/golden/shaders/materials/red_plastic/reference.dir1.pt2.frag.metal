#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    float3 _770 = fast::normalize(in.v_normal);
    float3 _776 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _931 = _770.y;
    float _936 = _770.z;
    float _941 = _770.x;
    float _1059 = fast::max(dot(_770, _776), 9.9999997473787516355514526367188e-05);
    float4 _1098 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1059, params.facet_perceptualRoughness), level(0.0));
    float3 _1117 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1098.y) - 1.0));
    float3 _1239 = fast::normalize(_776 + frame.lightDirection.xyz);
    float _1184 = fast::clamp(dot(_770, frame.lightDirection.xyz), 0.0, 1.0);
    float _1277 = 4096.0 * params.facet_alpha;
    float4 _1301 = float4(cross(_770, _1239), params.facet_alpha * fast::clamp(dot(_770, _1239), 0.0, 1.0)) * 64.0;
    float _1283 = _1277 / dot(_1301, _1301);
    float _1312 = params.facet_alpha * params.facet_alpha;
    float _1318 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1322 = sqrt(fma(_1059 * _1059, _1318, _1312));
    float _1345 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1239), 0.0, 1.0);
    float _1348 = _1345 * _1345;
    float3 _1356 = float3(1.0) - float3(params.facet_f0);
    float3 _1215 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1370 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _931)) + (frame.sh[2].xyz * _936)) + (frame.sh[3].xyz * _941)) + (((((frame.sh[4].xyz * (_941 * _931)) + (frame.sh[5].xyz * (_931 * _936))) + (frame.sh[6].xyz * fma(3.0 * _936, _936, -1.0))) + (frame.sh[7].xyz * (_941 * _936))) + (frame.sh[8].xyz * fma(_941, _941, -(_931 * _931)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_776, _770), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1098.xxx, _1098.yyy, float3(params.facet_f0)) * _1117)) + fast::min(fma((float3(params.facet_f0) + (_1356 * ((_1348 * _1348) * _1345))) * (((_1283 * _1283) * 0.3183098733425140380859375) * (0.5 / fma(_1184, _1322, _1059 * sqrt(fma(_1184 * _1184, _1318, _1312))))), _1117, _1215) * (frame.lightColor.xyz * _1184), float3(65504.0));
    float3 _1405 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1408 = dot(_1405, _1405);
    float3 _1413 = _1405 * rsqrt(fast::max(_1408, 9.9999999392252902907785028219223e-09));
    float _1417 = _1408 * float(frame.punctualLights[0].positionFalloff.w);
    float _1422 = fast::clamp(fma(-_1417, _1417, 1.0), 0.0, 1.0);
    float _1441 = fast::clamp(fma(dot(-_1413, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1556 = fast::normalize(_776 + _1413);
    float _1501 = fast::clamp(dot(_770, _1413), 0.0, 1.0);
    float4 _1618 = float4(cross(_770, _1556), params.facet_alpha * fast::clamp(dot(_770, _1556), 0.0, 1.0)) * 64.0;
    float _1600 = _1277 / dot(_1618, _1618);
    float _1662 = 1.0 - fast::clamp(dot(_1413, _1556), 0.0, 1.0);
    float _1665 = _1662 * _1662;
    float3 _1722 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1725 = dot(_1722, _1722);
    float3 _1730 = _1722 * rsqrt(fast::max(_1725, 9.9999999392252902907785028219223e-09));
    float _1734 = _1725 * float(frame.punctualLights[1].positionFalloff.w);
    float _1739 = fast::clamp(fma(-_1734, _1734, 1.0), 0.0, 1.0);
    float _1758 = fast::clamp(fma(dot(-_1730, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1873 = fast::normalize(_776 + _1730);
    float _1818 = fast::clamp(dot(_770, _1730), 0.0, 1.0);
    float4 _1935 = float4(cross(_770, _1873), params.facet_alpha * fast::clamp(dot(_770, _1873), 0.0, 1.0)) * 64.0;
    float _1917 = _1277 / dot(_1935, _1935);
    float _1979 = 1.0 - fast::clamp(dot(_1730, _1873), 0.0, 1.0);
    float _1982 = _1979 * _1979;
    float3 _2004 = (_1370 + fast::min(fma((float3(params.facet_f0) + (_1356 * ((_1665 * _1665) * _1662))) * (((_1600 * _1600) * 0.3183098733425140380859375) * (0.5 / fma(_1501, _1322, _1059 * sqrt(fma(_1501 * _1501, _1318, _1312))))), _1117, _1215) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1422 * _1422) / fast::max(_1408, 9.9999997473787516355514526367188e-05)) * _1441) * _1441)) * _1501), float3(65504.0))) + fast::min(fma((float3(params.facet_f0) + (_1356 * ((_1982 * _1982) * _1979))) * (((_1917 * _1917) * 0.3183098733425140380859375) * (0.5 / fma(_1818, _1322, _1059 * sqrt(fma(_1818 * _1818, _1318, _1312))))), _1117, _1215) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1739 * _1739) / fast::max(_1725, 9.9999997473787516355514526367188e-05)) * _1758) * _1758)) * _1818), float3(65504.0));
    out.fragColor = float4(_2004, 1.0);
    return out;
}

