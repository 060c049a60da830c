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
    float3 _644 = fast::normalize(in.v_normal);
    float3 _650 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _807 = _644.y;
    float _812 = _644.z;
    float _817 = _644.x;
    float _925 = fast::max(dot(_644, _650), 9.9999997473787516355514526367188e-05);
    float4 _930 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_925, params.facet_perceptualRoughness), level(0.0));
    float3 _976 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _943 = _930.z;
    float _945 = fma(-fast::max(_976.x, fast::max(_976.y, _976.z)), _943, 1.0);
    float _947 = _930.w;
    float _1010 = dot(_644, frame.lightDirection.xyz);
    float _1012 = fast::clamp(_1010, 0.0, 1.0);
    float _1026 = fast::clamp(dot(_644, fast::normalize(_650 + frame.lightDirection.xyz)), 0.0, 1.0);
    float _1108 = 2.0 + (1.0 / params.facet_alpha);
    float _1111 = 0.5 / params.facet_alpha;
    float3 _1137 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_650, _644), level(params.facet_perceptualRoughness * 4.0)).xyz, _976 * _943, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _807)) + (frame.sh[2].xyz * _812)) + (frame.sh[3].xyz * _817)) + (((((frame.sh[4].xyz * (_817 * _807)) + (frame.sh[5].xyz * (_807 * _812))) + (frame.sh[6].xyz * fma(3.0 * _812, _812, -1.0))) + (frame.sh[7].xyz * (_817 * _812))) + (frame.sh[8].xyz * fma(_817, _817, -(_807 * _807)))), float3(0.0))) * _945) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1010 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1012), float3(0.0), float3(1.0))) * _945) + (_976 * ((((_1108 * pow(fast::max(fma(-_1026, _1026, 1.0), 0.0), _1111)) * 0.15915493667125701904296875) * (_1012 / (4.0 * fma(-_1012, _925, _1012 + _925)))) * _947))) * frame.lightColor.xyz, float3(65504.0));
    float3 _1172 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1175 = dot(_1172, _1172);
    float3 _1180 = _1172 * rsqrt(fast::max(_1175, 9.9999999392252902907785028219223e-09));
    float _1184 = _1175 * float(frame.punctualLights[0].positionFalloff.w);
    float _1189 = fast::clamp(fma(-_1184, _1184, 1.0), 0.0, 1.0);
    float _1208 = fast::clamp(fma(dot(-_1180, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1243 = dot(_644, _1180);
    float _1245 = fast::clamp(_1243, 0.0, 1.0);
    float _1259 = fast::clamp(dot(_644, fast::normalize(_650 + _1180)), 0.0, 1.0);
    float3 _1405 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1408 = dot(_1405, _1405);
    float3 _1413 = _1405 * rsqrt(fast::max(_1408, 9.9999999392252902907785028219223e-09));
    float _1417 = _1408 * float(frame.punctualLights[1].positionFalloff.w);
    float _1422 = fast::clamp(fma(-_1417, _1417, 1.0), 0.0, 1.0);
    float _1441 = fast::clamp(fma(dot(-_1413, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1476 = dot(_644, _1413);
    float _1478 = fast::clamp(_1476, 0.0, 1.0);
    float _1492 = fast::clamp(dot(_644, fast::normalize(_650 + _1413)), 0.0, 1.0);
    float3 _1603 = (_1137 + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1243 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1245), float3(0.0), float3(1.0))) * _945) + (_976 * ((((_1108 * pow(fast::max(fma(-_1259, _1259, 1.0), 0.0), _1111)) * 0.15915493667125701904296875) * (_1245 / (4.0 * fma(-_1245, _925, _1245 + _925)))) * _947))) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1189 * _1189) / fast::max(_1175, 9.9999997473787516355514526367188e-05)) * _1208) * _1208)), float3(65504.0))) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1476 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1478), float3(0.0), float3(1.0))) * _945) + (_976 * ((((_1108 * pow(fast::max(fma(-_1492, _1492, 1.0), 0.0), _1111)) * 0.15915493667125701904296875) * (_1478 / (4.0 * fma(-_1478, _925, _1478 + _925)))) * _947))) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1422 * _1422) / fast::max(_1408, 9.9999997473787516355514526367188e-05)) * _1441) * _1441)), float3(65504.0));
    out.fragColor = float4(_1603, 1.0);
    return out;
}

