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
    float3 _667 = fast::normalize(in.v_normal);
    float3 _673 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _830 = _667.y;
    float _835 = _667.z;
    float _840 = _667.x;
    float _949 = fast::max(dot(_667, _673), 9.9999997473787516355514526367188e-05);
    float4 _954 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_949, params.facet_perceptualRoughness), level(0.0));
    float3 _1008 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _967 = _954.z;
    float _969 = fma(-fast::max(_1008.x, fast::max(_1008.y, _1008.z)), _967, 1.0);
    float _974 = _954.w;
    float _1047 = dot(_667, frame.lightDirection.xyz);
    float _1049 = fast::clamp(_1047, 0.0, 1.0);
    float _1061 = fast::clamp(dot(_667, fast::normalize(_673 + frame.lightDirection.xyz)), 0.0, 1.0);
    float _1130 = 8192.0 * fma(-_1049, _949, _1049 + _949);
    float _1134 = 1.0 / (params.facet_alpha * _1130);
    float _1141 = 2048.0 * params.facet_alpha;
    float3 _1169 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_673, _667), level(params.facet_perceptualRoughness * 4.0)).xyz, _1008 * _967, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _830)) + (frame.sh[2].xyz * _835)) + (frame.sh[3].xyz * _840)) + (((((frame.sh[4].xyz * (_840 * _830)) + (frame.sh[5].xyz * (_830 * _835))) + (frame.sh[6].xyz * fma(3.0 * _835, _835, -1.0))) + (frame.sh[7].xyz * (_840 * _835))) + (frame.sh[8].xyz * fma(_840, _840, -(_830 * _830)))), float3(0.0))) * _969) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1047 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1049), float3(0.0), float3(1.0))) * _969) + (_1008 * ((((fma(_1134, _1130, 2.0) * pow(fast::max(fma(-_1061, _1061, 1.0), 0.0), 0.5 * (_1134 * _1130))) * 0.15915493667125701904296875) * (_1049 * (_1134 * _1141))) * _974))) * frame.lightColor.xyz, float3(65504.0));
    float3 _1204 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1207 = dot(_1204, _1204);
    float3 _1212 = _1204 * rsqrt(fast::max(_1207, 9.9999999392252902907785028219223e-09));
    float _1216 = _1207 * float(frame.punctualLights[0].positionFalloff.w);
    float _1221 = fast::clamp(fma(-_1216, _1216, 1.0), 0.0, 1.0);
    float _1240 = fast::clamp(fma(dot(-_1212, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1271 = dot(_667, _1212);
    float _1273 = fast::clamp(_1271, 0.0, 1.0);
    float _1285 = fast::clamp(dot(_667, fast::normalize(_673 + _1212)), 0.0, 1.0);
    float _1354 = 8192.0 * fma(-_1273, _949, _1273 + _949);
    float _1358 = 1.0 / (params.facet_alpha * _1354);
    float3 _1428 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1431 = dot(_1428, _1428);
    float3 _1436 = _1428 * rsqrt(fast::max(_1431, 9.9999999392252902907785028219223e-09));
    float _1440 = _1431 * float(frame.punctualLights[1].positionFalloff.w);
    float _1445 = fast::clamp(fma(-_1440, _1440, 1.0), 0.0, 1.0);
    float _1464 = fast::clamp(fma(dot(-_1436, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1495 = dot(_667, _1436);
    float _1497 = fast::clamp(_1495, 0.0, 1.0);
    float _1509 = fast::clamp(dot(_667, fast::normalize(_673 + _1436)), 0.0, 1.0);
    float _1578 = 8192.0 * fma(-_1497, _949, _1497 + _949);
    float _1582 = 1.0 / (params.facet_alpha * _1578);
    float3 _1617 = (_1169 + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1271 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1273), float3(0.0), float3(1.0))) * _969) + (_1008 * ((((fma(_1358, _1354, 2.0) * pow(fast::max(fma(-_1285, _1285, 1.0), 0.0), 0.5 * (_1358 * _1354))) * 0.15915493667125701904296875) * (_1273 * (_1358 * _1141))) * _974))) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1221 * _1221) / fast::max(_1207, 9.9999997473787516355514526367188e-05)) * _1240) * _1240)), float3(65504.0))) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1495 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1497), float3(0.0), float3(1.0))) * _969) + (_1008 * ((((fma(_1582, _1578, 2.0) * pow(fast::max(fma(-_1509, _1509, 1.0), 0.0), 0.5 * (_1582 * _1578))) * 0.15915493667125701904296875) * (_1497 * (_1582 * _1141))) * _974))) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1445 * _1445) / fast::max(_1431, 9.9999997473787516355514526367188e-05)) * _1464) * _1464)), float3(65504.0));
    out.fragColor = float4(_1617, 1.0);
    return out;
}

