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
    float3 _636 = fast::normalize(in.v_normal);
    float3 _642 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _778 = _636.y;
    float _783 = _636.z;
    float _788 = _636.x;
    float _896 = fast::max(dot(_636, _642), 9.9999997473787516355514526367188e-05);
    float4 _901 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_896, params.facet_perceptualRoughness), level(0.0));
    float3 _947 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _914 = _901.z;
    float _916 = fma(-fast::max(_947.x, fast::max(_947.y, _947.z)), _914, 1.0);
    float _918 = _901.w;
    float3 _990 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _993 = dot(_990, _990);
    float3 _998 = _990 * rsqrt(fast::max(_993, 9.9999999392252902907785028219223e-09));
    float _1002 = _993 * float(frame.punctualLights[0].positionFalloff.w);
    float _1007 = fast::clamp(fma(-_1002, _1002, 1.0), 0.0, 1.0);
    float _1026 = fast::clamp(fma(dot(-_998, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1061 = dot(_636, _998);
    float _1063 = fast::clamp(_1061, 0.0, 1.0);
    float _1077 = fast::clamp(dot(_636, fast::normalize(_642 + _998)), 0.0, 1.0);
    float _1148 = 8192.0 * fma(-_1063, _896, _1063 + _896);
    float _1152 = 1.0 / (params.facet_alpha * _1148);
    float _1159 = 2048.0 * params.facet_alpha;
    float3 _1187 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_642, _636), level(params.facet_perceptualRoughness * 4.0)).xyz, _947 * _914, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _778)) + (frame.sh[2].xyz * _783)) + (frame.sh[3].xyz * _788)) + (((((frame.sh[4].xyz * (_788 * _778)) + (frame.sh[5].xyz * (_778 * _783))) + (frame.sh[6].xyz * fma(3.0 * _783, _783, -1.0))) + (frame.sh[7].xyz * (_788 * _783))) + (frame.sh[8].xyz * fma(_788, _788, -(_778 * _778)))), float3(0.0))) * _916) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1061 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1063), float3(0.0), float3(1.0))) * _916) + (_947 * ((((fma(_1152, _1148, 2.0) * pow(fast::max(fma(-_1077, _1077, 1.0), 0.0), 0.5 * (_1152 * _1148))) * 0.15915493667125701904296875) * (_1063 * (_1152 * _1159))) * _918))) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1007 * _1007) / fast::max(_993, 9.9999997473787516355514526367188e-05)) * _1026) * _1026)), float3(65504.0));
    float3 _1222 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1225 = dot(_1222, _1222);
    float3 _1230 = _1222 * rsqrt(fast::max(_1225, 9.9999999392252902907785028219223e-09));
    float _1234 = _1225 * float(frame.punctualLights[1].positionFalloff.w);
    float _1239 = fast::clamp(fma(-_1234, _1234, 1.0), 0.0, 1.0);
    float _1258 = fast::clamp(fma(dot(-_1230, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1293 = dot(_636, _1230);
    float _1295 = fast::clamp(_1293, 0.0, 1.0);
    float _1309 = fast::clamp(dot(_636, fast::normalize(_642 + _1230)), 0.0, 1.0);
    float _1380 = 8192.0 * fma(-_1295, _896, _1295 + _896);
    float _1384 = 1.0 / (params.facet_alpha * _1380);
    out.fragColor = float4(_1187 + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1293 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1295), float3(0.0), float3(1.0))) * _916) + (_947 * ((((fma(_1384, _1380, 2.0) * pow(fast::max(fma(-_1309, _1309, 1.0), 0.0), 0.5 * (_1384 * _1380))) * 0.15915493667125701904296875) * (_1295 * (_1384 * _1159))) * _918))) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1239 * _1239) / fast::max(_1225, 9.9999997473787516355514526367188e-05)) * _1258) * _1258)), float3(65504.0)), 1.0);
    return out;
}

