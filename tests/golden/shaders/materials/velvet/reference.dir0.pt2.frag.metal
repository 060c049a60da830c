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
    float _814 = _672.y;
    float _819 = _672.z;
    float _824 = _672.x;
    float _933 = fast::max(dot(_672, _678), 9.9999997473787516355514526367188e-05);
    float4 _938 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_933, params.facet_perceptualRoughness), level(0.0));
    float3 _992 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _951 = _938.z;
    float _953 = fma(-fast::max(_992.x, fast::max(_992.y, _992.z)), _951, 1.0);
    float _958 = _938.w;
    float3 _1049 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1052 = dot(_1049, _1049);
    float3 _1057 = _1049 * rsqrt(fast::max(_1052, 9.9999999392252902907785028219223e-09));
    float _1061 = _1052 * float(frame.punctualLights[0].positionFalloff.w);
    float _1066 = fast::clamp(fma(-_1061, _1061, 1.0), 0.0, 1.0);
    float _1085 = fast::clamp(fma(dot(-_1057, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1116 = dot(_672, _1057);
    float _1118 = fast::clamp(_1116, 0.0, 1.0);
    float _1130 = fast::clamp(dot(_672, fast::normalize(_678 + _1057)), 0.0, 1.0);
    float _1199 = 8192.0 * fma(-_1118, _933, _1118 + _933);
    float _1203 = 1.0 / (params.facet_alpha * _1199);
    float _1210 = 2048.0 * params.facet_alpha;
    float3 _1238 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_678, _672), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, _992 * _951, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _814)) + (frame.sh[2].xyz * _819)) + (frame.sh[3].xyz * _824)) + (((((frame.sh[4].xyz * (_824 * _814)) + (frame.sh[5].xyz * (_814 * _819))) + (frame.sh[6].xyz * fma(3.0 * _819, _819, -1.0))) + (frame.sh[7].xyz * (_824 * _819))) + (frame.sh[8].xyz * fma(_824, _824, -(_814 * _814)))), float3(0.0))) * _953) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1116 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1118), float3(0.0), float3(1.0))) * _953) + (_992 * ((((fma(_1203, _1199, 2.0) * pow(fast::max(fma(-_1130, _1130, 1.0), 0.0), 0.5 * (_1203 * _1199))) * 0.15915493667125701904296875) * (_1118 * (_1203 * _1210))) * _958))) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1066 * _1066) / fast::max(_1052, 9.9999997473787516355514526367188e-05)) * _1085) * _1085)), float3(65504.0));
    float3 _1273 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1276 = dot(_1273, _1273);
    float3 _1281 = _1273 * rsqrt(fast::max(_1276, 9.9999999392252902907785028219223e-09));
    float _1285 = _1276 * float(frame.punctualLights[1].positionFalloff.w);
    float _1290 = fast::clamp(fma(-_1285, _1285, 1.0), 0.0, 1.0);
    float _1309 = fast::clamp(fma(dot(-_1281, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1340 = dot(_672, _1281);
    float _1342 = fast::clamp(_1340, 0.0, 1.0);
    float _1354 = fast::clamp(dot(_672, fast::normalize(_678 + _1281)), 0.0, 1.0);
    float _1423 = 8192.0 * fma(-_1342, _933, _1342 + _933);
    float _1427 = 1.0 / (params.facet_alpha * _1423);
    out.fragColor = float4(_1238 + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1340 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1342), float3(0.0), float3(1.0))) * _953) + (_992 * ((((fma(_1427, _1423, 2.0) * pow(fast::max(fma(-_1354, _1354, 1.0), 0.0), 0.5 * (_1427 * _1423))) * 0.15915493667125701904296875) * (_1342 * (_1427 * _1210))) * _958))) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1290 * _1290) / fast::max(_1276, 9.9999997473787516355514526367188e-05)) * _1309) * _1309)), float3(65504.0)), 1.0);
    return out;
}

