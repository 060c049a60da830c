#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    float3 _670 = fast::normalize(in.v_normal);
    float3 _676 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _833 = _670.y;
    float _838 = _670.z;
    float _843 = _670.x;
    float _952 = fast::max(dot(_670, _676), 9.9999997473787516355514526367188e-05);
    float4 _957 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_952, params.facet_perceptualRoughness), level(0.0));
    float3 _1011 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _970 = _957.z;
    float _972 = fma(-fast::max(_1011.x, fast::max(_1011.y, _1011.z)), _970, 1.0);
    float _977 = _957.w;
    float _1053 = dot(_670, frame.lightDirection.xyz);
    float _1055 = fast::clamp(_1053, 0.0, 1.0);
    float _1067 = fast::clamp(dot(_670, fast::normalize(_676 + frame.lightDirection.xyz)), 0.0, 1.0);
    float _1136 = 8192.0 * fma(-_1055, _952, _1055 + _952);
    float _1140 = 1.0 / (params.facet_alpha * _1136);
    float _1147 = 2048.0 * params.facet_alpha;
    float3 _1175 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_676, _670), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, _1011 * _970, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _833)) + (frame.sh[2].xyz * _838)) + (frame.sh[3].xyz * _843)) + (((((frame.sh[4].xyz * (_843 * _833)) + (frame.sh[5].xyz * (_833 * _838))) + (frame.sh[6].xyz * fma(3.0 * _838, _838, -1.0))) + (frame.sh[7].xyz * (_843 * _838))) + (frame.sh[8].xyz * fma(_843, _843, -(_833 * _833)))), float3(0.0))) * _972) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1053 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1055), float3(0.0), float3(1.0))) * _972) + (_1011 * ((((fma(_1140, _1136, 2.0) * pow(fast::max(fma(-_1067, _1067, 1.0), 0.0), 0.5 * (_1140 * _1136))) * 0.15915493667125701904296875) * (_1055 * (_1140 * _1147))) * _977))) * frame.lightColor.xyz, float3(65504.0));
    float3 _1210 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1213 = dot(_1210, _1210);
    float3 _1218 = _1210 * rsqrt(fast::max(_1213, 9.9999999392252902907785028219223e-09));
    float _1222 = _1213 * float(frame.punctualLights[0].positionFalloff.w);
    float _1227 = fast::clamp(fma(-_1222, _1222, 1.0), 0.0, 1.0);
    float _1246 = fast::clamp(fma(dot(-_1218, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1277 = dot(_670, _1218);
    float _1279 = fast::clamp(_1277, 0.0, 1.0);
    float _1291 = fast::clamp(dot(_670, fast::normalize(_676 + _1218)), 0.0, 1.0);
    float _1360 = 8192.0 * fma(-_1279, _952, _1279 + _952);
    float _1364 = 1.0 / (params.facet_alpha * _1360);
    float3 _1434 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1437 = dot(_1434, _1434);
    float3 _1442 = _1434 * rsqrt(fast::max(_1437, 9.9999999392252902907785028219223e-09));
    float _1446 = _1437 * float(frame.punctualLights[1].positionFalloff.w);
    float _1451 = fast::clamp(fma(-_1446, _1446, 1.0), 0.0, 1.0);
    float _1470 = fast::clamp(fma(dot(-_1442, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1501 = dot(_670, _1442);
    float _1503 = fast::clamp(_1501, 0.0, 1.0);
    float _1515 = fast::clamp(dot(_670, fast::normalize(_676 + _1442)), 0.0, 1.0);
    float _1584 = 8192.0 * fma(-_1503, _952, _1503 + _952);
    float _1588 = 1.0 / (params.facet_alpha * _1584);
    float3 _1623 = (_1175 + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1277 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1279), float3(0.0), float3(1.0))) * _972) + (_1011 * ((((fma(_1364, _1360, 2.0) * pow(fast::max(fma(-_1291, _1291, 1.0), 0.0), 0.5 * (_1364 * _1360))) * 0.15915493667125701904296875) * (_1279 * (_1364 * _1147))) * _977))) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1227 * _1227) / fast::max(_1213, 9.9999997473787516355514526367188e-05)) * _1246) * _1246)), float3(65504.0))) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1501 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1503), float3(0.0), float3(1.0))) * _972) + (_1011 * ((((fma(_1588, _1584, 2.0) * pow(fast::max(fma(-_1515, _1515, 1.0), 0.0), 0.5 * (_1588 * _1584))) * 0.15915493667125701904296875) * (_1503 * (_1588 * _1147))) * _977))) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1451 * _1451) / fast::max(_1437, 9.9999997473787516355514526367188e-05)) * _1470) * _1470)), float3(65504.0));
    out.fragColor = float4(_1623, 1.0);
    return out;
}

