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
    float _809 = _667.y;
    float _814 = _667.z;
    float _819 = _667.x;
    float _928 = fast::max(dot(_667, _673), 9.9999997473787516355514526367188e-05);
    float4 _933 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_928, params.facet_perceptualRoughness), level(0.0));
    float3 _987 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _946 = _933.z;
    float _948 = fma(-fast::max(_987.x, fast::max(_987.y, _987.z)), _946, 1.0);
    float _953 = _933.w;
    float3 _1039 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1042 = dot(_1039, _1039);
    float3 _1047 = _1039 * rsqrt(fast::max(_1042, 9.9999999392252902907785028219223e-09));
    float _1051 = _1042 * float(frame.punctualLights[0].positionFalloff.w);
    float _1056 = fast::clamp(fma(-_1051, _1051, 1.0), 0.0, 1.0);
    float _1075 = fast::clamp(fma(dot(-_1047, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1106 = dot(_667, _1047);
    float _1108 = fast::clamp(_1106, 0.0, 1.0);
    float _1120 = fast::clamp(dot(_667, fast::normalize(_673 + _1047)), 0.0, 1.0);
    float _1189 = 8192.0 * fma(-_1108, _928, _1108 + _928);
    float _1193 = 1.0 / (params.facet_alpha * _1189);
    float _1200 = 2048.0 * params.facet_alpha;
    float3 _1228 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_673, _667), level(params.facet_perceptualRoughness * 4.0)).xyz, _987 * _946, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _809)) + (frame.sh[2].xyz * _814)) + (frame.sh[3].xyz * _819)) + (((((frame.sh[4].xyz * (_819 * _809)) + (frame.sh[5].xyz * (_809 * _814))) + (frame.sh[6].xyz * fma(3.0 * _814, _814, -1.0))) + (frame.sh[7].xyz * (_819 * _814))) + (frame.sh[8].xyz * fma(_819, _819, -(_809 * _809)))), float3(0.0))) * _948) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1106 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1108), float3(0.0), float3(1.0))) * _948) + (_987 * ((((fma(_1193, _1189, 2.0) * pow(fast::max(fma(-_1120, _1120, 1.0), 0.0), 0.5 * (_1193 * _1189))) * 0.15915493667125701904296875) * (_1108 * (_1193 * _1200))) * _953))) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1056 * _1056) / fast::max(_1042, 9.9999997473787516355514526367188e-05)) * _1075) * _1075)), float3(65504.0));
    float3 _1263 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1266 = dot(_1263, _1263);
    float3 _1271 = _1263 * rsqrt(fast::max(_1266, 9.9999999392252902907785028219223e-09));
    float _1275 = _1266 * float(frame.punctualLights[1].positionFalloff.w);
    float _1280 = fast::clamp(fma(-_1275, _1275, 1.0), 0.0, 1.0);
    float _1299 = fast::clamp(fma(dot(-_1271, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1330 = dot(_667, _1271);
    float _1332 = fast::clamp(_1330, 0.0, 1.0);
    float _1344 = fast::clamp(dot(_667, fast::normalize(_673 + _1271)), 0.0, 1.0);
    float _1413 = 8192.0 * fma(-_1332, _928, _1332 + _928);
    float _1417 = 1.0 / (params.facet_alpha * _1413);
    out.fragColor = float4(_1228 + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1330 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1332), float3(0.0), float3(1.0))) * _948) + (_987 * ((((fma(_1417, _1413, 2.0) * pow(fast::max(fma(-_1344, _1344, 1.0), 0.0), 0.5 * (_1417 * _1413))) * 0.15915493667125701904296875) * (_1332 * (_1417 * _1200))) * _953))) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1280 * _1280) / fast::max(_1266, 9.9999997473787516355514526367188e-05)) * _1299) * _1299)), float3(65504.0)), 1.0);
    return out;
}

