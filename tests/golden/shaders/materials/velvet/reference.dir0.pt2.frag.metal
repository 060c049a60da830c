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
    float _818 = _676.y;
    float _823 = _676.z;
    float _828 = _676.x;
    float _936 = fast::max(dot(_676, _682), 9.9999997473787516355514526367188e-05);
    float4 _941 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_936, params.facet_perceptualRoughness), level(0.0));
    float3 _992 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _954 = _941.z;
    float _956 = fma(-fast::max(_992.x, fast::max(_992.y, _992.z)), _954, 1.0);
    float _958 = _941.w;
    float3 _1035 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1038 = dot(_1035, _1035);
    float3 _1043 = _1035 * rsqrt(fast::max(_1038, 9.9999999392252902907785028219223e-09));
    float _1047 = _1038 * float(frame.punctualLights[0].positionFalloff.w);
    float _1052 = fast::clamp(fma(-_1047, _1047, 1.0), 0.0, 1.0);
    float _1071 = fast::clamp(fma(dot(-_1043, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1097 = dot(_676, _1043);
    float _1099 = fast::clamp(_1097, 0.0, 1.0);
    float _1167 = fast::clamp(dot(_676, fast::normalize(_682 + _1043)), 0.0, 1.0);
    float _1209 = 8192.0 * fma(-_1099, _936, _1099 + _936);
    float _1213 = 1.0 / (params.facet_alpha * _1209);
    float _1220 = 2048.0 * params.facet_alpha;
    float3 _1255 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_682, _676), level(params.facet_perceptualRoughness * 4.0)).xyz, _992 * _954, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _818)) + (frame.sh[2].xyz * _823)) + (frame.sh[3].xyz * _828)) + (((((frame.sh[4].xyz * (_828 * _818)) + (frame.sh[5].xyz * (_818 * _823))) + (frame.sh[6].xyz * fma(3.0 * _823, _823, -1.0))) + (frame.sh[7].xyz * (_828 * _823))) + (frame.sh[8].xyz * fma(_828, _828, -(_818 * _818)))), float3(0.0))) * _956) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1097 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1099), float3(0.0), float3(1.0))) * _956) + (_992 * ((((fma(_1213, _1209, 2.0) * pow(fast::max(fma(-_1167, _1167, 1.0), 0.0), 0.5 * (_1213 * _1209))) * 0.15915493667125701904296875) * (_1099 * (_1213 * _1220))) * _958))) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1052 * _1052) / fast::max(_1038, 9.9999997473787516355514526367188e-05)) * _1071) * _1071)), float3(65504.0));
    float3 _1290 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1293 = dot(_1290, _1290);
    float3 _1298 = _1290 * rsqrt(fast::max(_1293, 9.9999999392252902907785028219223e-09));
    float _1302 = _1293 * float(frame.punctualLights[1].positionFalloff.w);
    float _1307 = fast::clamp(fma(-_1302, _1302, 1.0), 0.0, 1.0);
    float _1326 = fast::clamp(fma(dot(-_1298, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1352 = dot(_676, _1298);
    float _1354 = fast::clamp(_1352, 0.0, 1.0);
    float _1422 = fast::clamp(dot(_676, fast::normalize(_682 + _1298)), 0.0, 1.0);
    float _1464 = 8192.0 * fma(-_1354, _936, _1354 + _936);
    float _1468 = 1.0 / (params.facet_alpha * _1464);
    out.fragColor = float4(_1255 + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1352 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1354), float3(0.0), float3(1.0))) * _956) + (_992 * ((((fma(_1468, _1464, 2.0) * pow(fast::max(fma(-_1422, _1422, 1.0), 0.0), 0.5 * (_1468 * _1464))) * 0.15915493667125701904296875) * (_1354 * (_1468 * _1220))) * _958))) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1307 * _1307) / fast::max(_1293, 9.9999997473787516355514526367188e-05)) * _1326) * _1326)), float3(65504.0)), 1.0);
    return out;
}

