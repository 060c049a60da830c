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
    float3 _676 = fast::normalize(in.v_normal);
    float3 _682 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _839 = _676.y;
    float _844 = _676.z;
    float _849 = _676.x;
    float _957 = fast::max(dot(_676, _682), 9.9999997473787516355514526367188e-05);
    float4 _962 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_957, params.facet_perceptualRoughness), level(0.0));
    float3 _1013 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _975 = _962.z;
    float _977 = fma(-fast::max(_1013.x, fast::max(_1013.y, _1013.z)), _975, 1.0);
    float _979 = _962.w;
    float _1038 = dot(_676, frame.lightDirection.xyz);
    float _1040 = fast::clamp(_1038, 0.0, 1.0);
    float _1108 = fast::clamp(dot(_676, fast::normalize(_682 + frame.lightDirection.xyz)), 0.0, 1.0);
    float _1150 = 8192.0 * fma(-_1040, _957, _1040 + _957);
    float _1154 = 1.0 / (params.facet_alpha * _1150);
    float _1161 = 2048.0 * params.facet_alpha;
    float3 _1196 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_682, _676), level(params.facet_perceptualRoughness * 4.0)).xyz, _1013 * _975, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _839)) + (frame.sh[2].xyz * _844)) + (frame.sh[3].xyz * _849)) + (((((frame.sh[4].xyz * (_849 * _839)) + (frame.sh[5].xyz * (_839 * _844))) + (frame.sh[6].xyz * fma(3.0 * _844, _844, -1.0))) + (frame.sh[7].xyz * (_849 * _844))) + (frame.sh[8].xyz * fma(_849, _849, -(_839 * _839)))), float3(0.0))) * _977) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1038 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1040), float3(0.0), float3(1.0))) * _977) + (_1013 * ((((fma(_1154, _1150, 2.0) * pow(fast::max(fma(-_1108, _1108, 1.0), 0.0), 0.5 * (_1154 * _1150))) * 0.15915493667125701904296875) * (_1040 * (_1154 * _1161))) * _979))) * frame.lightColor.xyz, float3(65504.0));
    float3 _1231 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1234 = dot(_1231, _1231);
    float3 _1239 = _1231 * rsqrt(fast::max(_1234, 9.9999999392252902907785028219223e-09));
    float _1243 = _1234 * float(frame.punctualLights[0].positionFalloff.w);
    float _1248 = fast::clamp(fma(-_1243, _1243, 1.0), 0.0, 1.0);
    float _1267 = fast::clamp(fma(dot(-_1239, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1293 = dot(_676, _1239);
    float _1295 = fast::clamp(_1293, 0.0, 1.0);
    float _1363 = fast::clamp(dot(_676, fast::normalize(_682 + _1239)), 0.0, 1.0);
    float _1405 = 8192.0 * fma(-_1295, _957, _1295 + _957);
    float _1409 = 1.0 / (params.facet_alpha * _1405);
    float3 _1486 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1489 = dot(_1486, _1486);
    float3 _1494 = _1486 * rsqrt(fast::max(_1489, 9.9999999392252902907785028219223e-09));
    float _1498 = _1489 * float(frame.punctualLights[1].positionFalloff.w);
    float _1503 = fast::clamp(fma(-_1498, _1498, 1.0), 0.0, 1.0);
    float _1522 = fast::clamp(fma(dot(-_1494, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1548 = dot(_676, _1494);
    float _1550 = fast::clamp(_1548, 0.0, 1.0);
    float _1618 = fast::clamp(dot(_676, fast::normalize(_682 + _1494)), 0.0, 1.0);
    float _1660 = 8192.0 * fma(-_1550, _957, _1550 + _957);
    float _1664 = 1.0 / (params.facet_alpha * _1660);
    float3 _1706 = (_1196 + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1293 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1295), float3(0.0), float3(1.0))) * _977) + (_1013 * ((((fma(_1409, _1405, 2.0) * pow(fast::max(fma(-_1363, _1363, 1.0), 0.0), 0.5 * (_1409 * _1405))) * 0.15915493667125701904296875) * (_1295 * (_1409 * _1161))) * _979))) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1248 * _1248) / fast::max(_1234, 9.9999997473787516355514526367188e-05)) * _1267) * _1267)), float3(65504.0))) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1548 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1550), float3(0.0), float3(1.0))) * _977) + (_1013 * ((((fma(_1664, _1660, 2.0) * pow(fast::max(fma(-_1618, _1618, 1.0), 0.0), 0.5 * (_1664 * _1660))) * 0.15915493667125701904296875) * (_1550 * (_1664 * _1161))) * _979))) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1503 * _1503) / fast::max(_1489, 9.9999997473787516355514526367188e-05)) * _1522) * _1522)), float3(65504.0));
    out.fragColor = float4(_1706, 1.0);
    return out;
}

