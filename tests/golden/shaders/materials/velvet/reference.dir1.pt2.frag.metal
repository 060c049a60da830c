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
    float3 _672 = fast::normalize(in.v_normal);
    float3 _678 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _835 = _672.y;
    float _840 = _672.z;
    float _845 = _672.x;
    float _954 = fast::max(dot(_672, _678), 9.9999997473787516355514526367188e-05);
    float4 _959 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_954, params.facet_perceptualRoughness), level(0.0));
    float3 _1013 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _972 = _959.z;
    float _974 = fma(-fast::max(_1013.x, fast::max(_1013.y, _1013.z)), _972, 1.0);
    float _979 = _959.w;
    float _1057 = dot(_672, frame.lightDirection.xyz);
    float _1059 = fast::clamp(_1057, 0.0, 1.0);
    float _1071 = fast::clamp(dot(_672, fast::normalize(_678 + frame.lightDirection.xyz)), 0.0, 1.0);
    float _1140 = 8192.0 * fma(-_1059, _954, _1059 + _954);
    float _1144 = 1.0 / (params.facet_alpha * _1140);
    float _1151 = 2048.0 * params.facet_alpha;
    float3 _1179 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_678, _672), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, _1013 * _972, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _835)) + (frame.sh[2].xyz * _840)) + (frame.sh[3].xyz * _845)) + (((((frame.sh[4].xyz * (_845 * _835)) + (frame.sh[5].xyz * (_835 * _840))) + (frame.sh[6].xyz * fma(3.0 * _840, _840, -1.0))) + (frame.sh[7].xyz * (_845 * _840))) + (frame.sh[8].xyz * fma(_845, _845, -(_835 * _835)))), float3(0.0))) * _974) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1057 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1059), float3(0.0), float3(1.0))) * _974) + (_1013 * ((((fma(_1144, _1140, 2.0) * pow(fast::max(fma(-_1071, _1071, 1.0), 0.0), 0.5 * (_1144 * _1140))) * 0.15915493667125701904296875) * (_1059 * (_1144 * _1151))) * _979))) * frame.lightColor.xyz, float3(65504.0));
    float3 _1214 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1217 = dot(_1214, _1214);
    float3 _1222 = _1214 * rsqrt(fast::max(_1217, 9.9999999392252902907785028219223e-09));
    float _1226 = _1217 * float(frame.punctualLights[0].positionFalloff.w);
    float _1231 = fast::clamp(fma(-_1226, _1226, 1.0), 0.0, 1.0);
    float _1250 = fast::clamp(fma(dot(-_1222, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1281 = dot(_672, _1222);
    float _1283 = fast::clamp(_1281, 0.0, 1.0);
    float _1295 = fast::clamp(dot(_672, fast::normalize(_678 + _1222)), 0.0, 1.0);
    float _1364 = 8192.0 * fma(-_1283, _954, _1283 + _954);
    float _1368 = 1.0 / (params.facet_alpha * _1364);
    float3 _1438 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1441 = dot(_1438, _1438);
    float3 _1446 = _1438 * rsqrt(fast::max(_1441, 9.9999999392252902907785028219223e-09));
    float _1450 = _1441 * float(frame.punctualLights[1].positionFalloff.w);
    float _1455 = fast::clamp(fma(-_1450, _1450, 1.0), 0.0, 1.0);
    float _1474 = fast::clamp(fma(dot(-_1446, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1505 = dot(_672, _1446);
    float _1507 = fast::clamp(_1505, 0.0, 1.0);
    float _1519 = fast::clamp(dot(_672, fast::normalize(_678 + _1446)), 0.0, 1.0);
    float _1588 = 8192.0 * fma(-_1507, _954, _1507 + _954);
    float _1592 = 1.0 / (params.facet_alpha * _1588);
    float3 _1627 = (_1179 + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1281 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1283), float3(0.0), float3(1.0))) * _974) + (_1013 * ((((fma(_1368, _1364, 2.0) * pow(fast::max(fma(-_1295, _1295, 1.0), 0.0), 0.5 * (_1368 * _1364))) * 0.15915493667125701904296875) * (_1283 * (_1368 * _1151))) * _979))) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1231 * _1231) / fast::max(_1217, 9.9999997473787516355514526367188e-05)) * _1250) * _1250)), float3(65504.0))) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1505 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1507), float3(0.0), float3(1.0))) * _974) + (_1013 * ((((fma(_1592, _1588, 2.0) * pow(fast::max(fma(-_1519, _1519, 1.0), 0.0), 0.5 * (_1592 * _1588))) * 0.15915493667125701904296875) * (_1507 * (_1592 * _1151))) * _979))) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1455 * _1455) / fast::max(_1441, 9.9999997473787516355514526367188e-05)) * _1474) * _1474)), float3(65504.0));
    out.fragColor = float4(_1627, 1.0);
    return out;
}

