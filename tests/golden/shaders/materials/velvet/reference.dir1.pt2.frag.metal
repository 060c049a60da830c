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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
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
    float3 _653 = fast::normalize(in.v_normal);
    float3 _659 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _816 = _653.y;
    float _821 = _653.z;
    float _826 = _653.x;
    float _933 = fast::max(dot(_653, _659), 9.9999997473787516355514526367188e-05);
    float4 _938 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_933, params.facet_perceptualRoughness), level(0.0));
    float _951 = _938.z;
    float _953 = fma(-fast::max(params.facet_sheenColor[0], fast::max(params.facet_sheenColor[1], params.facet_sheenColor[2])), _951, 1.0);
    float _958 = _938.w;
    float _1023 = dot(_653, frame.lightDirection.xyz);
    float _1025 = fast::clamp(_1023, 0.0, 1.0);
    float _1037 = fast::clamp(dot(_653, fast::normalize(_659 + frame.lightDirection.xyz)), 0.0, 1.0);
    float _1106 = 8192.0 * fma(-_1025, _933, _1025 + _933);
    float _1110 = 1.0 / (params.facet_alpha * _1106);
    float _1117 = 2048.0 * params.facet_alpha;
    float3 _1145 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_659, _653), level(params.facet_sheenLod)).xyz, float3(params.facet_sheenColor) * _951, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _816)) + (frame.sh[2].xyz * _821)) + (frame.sh[3].xyz * _826)) + (((((frame.sh[4].xyz * (_826 * _816)) + (frame.sh[5].xyz * (_816 * _821))) + (frame.sh[6].xyz * fma(3.0 * _821, _821, -1.0))) + (frame.sh[7].xyz * (_826 * _821))) + (frame.sh[8].xyz * fma(_826, _826, -(_816 * _816)))), float3(0.0))) * _953) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1023 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1025), float3(0.0), float3(1.0))) * _953) + (float3(params.facet_sheenColor) * ((((fma(_1110, _1106, 2.0) * pow(fast::max(fma(-_1037, _1037, 1.0), 0.0), 0.5 * (_1110 * _1106))) * 0.15915493667125701904296875) * (_1025 * (_1110 * _1117))) * _958))) * frame.lightColor.xyz, float3(65504.0));
    float3 _1180 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1183 = dot(_1180, _1180);
    float3 _1188 = _1180 * rsqrt(fast::max(_1183, 9.9999999392252902907785028219223e-09));
    float _1192 = _1183 * float(frame.punctualLights[0].positionFalloff.w);
    float _1197 = fast::clamp(fma(-_1192, _1192, 1.0), 0.0, 1.0);
    float _1216 = fast::clamp(fma(dot(-_1188, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1247 = dot(_653, _1188);
    float _1249 = fast::clamp(_1247, 0.0, 1.0);
    float _1261 = fast::clamp(dot(_653, fast::normalize(_659 + _1188)), 0.0, 1.0);
    float _1330 = 8192.0 * fma(-_1249, _933, _1249 + _933);
    float _1334 = 1.0 / (params.facet_alpha * _1330);
    float3 _1404 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1407 = dot(_1404, _1404);
    float3 _1412 = _1404 * rsqrt(fast::max(_1407, 9.9999999392252902907785028219223e-09));
    float _1416 = _1407 * float(frame.punctualLights[1].positionFalloff.w);
    float _1421 = fast::clamp(fma(-_1416, _1416, 1.0), 0.0, 1.0);
    float _1440 = fast::clamp(fma(dot(-_1412, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1471 = dot(_653, _1412);
    float _1473 = fast::clamp(_1471, 0.0, 1.0);
    float _1485 = fast::clamp(dot(_653, fast::normalize(_659 + _1412)), 0.0, 1.0);
    float _1554 = 8192.0 * fma(-_1473, _933, _1473 + _933);
    float _1558 = 1.0 / (params.facet_alpha * _1554);
    float3 _1593 = (_1145 + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1247 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1249), float3(0.0), float3(1.0))) * _953) + (float3(params.facet_sheenColor) * ((((fma(_1334, _1330, 2.0) * pow(fast::max(fma(-_1261, _1261, 1.0), 0.0), 0.5 * (_1334 * _1330))) * 0.15915493667125701904296875) * (_1249 * (_1334 * _1117))) * _958))) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1197 * _1197) / fast::max(_1183, 9.9999997473787516355514526367188e-05)) * _1216) * _1216)), float3(65504.0))) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1471 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1473), float3(0.0), float3(1.0))) * _953) + (float3(params.facet_sheenColor) * ((((fma(_1558, _1554, 2.0) * pow(fast::max(fma(-_1485, _1485, 1.0), 0.0), 0.5 * (_1558 * _1554))) * 0.15915493667125701904296875) * (_1473 * (_1558 * _1117))) * _958))) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1421 * _1421) / fast::max(_1407, 9.9999997473787516355514526367188e-05)) * _1440) * _1440)), float3(65504.0));
    out.fragColor = float4(_1593, 1.0);
    return out;
}

