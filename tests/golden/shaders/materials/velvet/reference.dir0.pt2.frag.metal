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
    float _811 = _667.y;
    float _816 = _667.z;
    float _821 = _667.x;
    float _930 = fast::max(dot(_667, _673), 9.9999997473787516355514526367188e-05);
    float4 _935 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_930, params.facet_perceptualRoughness), level(0.0));
    float3 _989 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _948 = _935.z;
    float _950 = fma(-fast::max(_989.x, fast::max(_989.y, _989.z)), _948, 1.0);
    float _955 = _935.w;
    float3 _1041 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1044 = dot(_1041, _1041);
    float3 _1049 = _1041 * rsqrt(fast::max(_1044, 9.9999999392252902907785028219223e-09));
    float _1053 = _1044 * float(frame.punctualLights[0].positionFalloff.w);
    float _1058 = fast::clamp(fma(-_1053, _1053, 1.0), 0.0, 1.0);
    float _1077 = fast::clamp(fma(dot(-_1049, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1108 = dot(_667, _1049);
    float _1110 = fast::clamp(_1108, 0.0, 1.0);
    float _1122 = fast::clamp(dot(_667, fast::normalize(_673 + _1049)), 0.0, 1.0);
    float _1191 = 8192.0 * fma(-_1110, _930, _1110 + _930);
    float _1195 = 1.0 / (params.facet_alpha * _1191);
    float _1202 = 2048.0 * params.facet_alpha;
    float3 _1230 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_673, _667), level(params.facet_perceptualRoughness * 4.0)).xyz, _989 * _948, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _811)) + (frame.sh[2].xyz * _816)) + (frame.sh[3].xyz * _821)) + (((((frame.sh[4].xyz * (_821 * _811)) + (frame.sh[5].xyz * (_811 * _816))) + (frame.sh[6].xyz * fma(3.0 * _816, _816, -1.0))) + (frame.sh[7].xyz * (_821 * _816))) + (frame.sh[8].xyz * fma(_821, _821, -(_811 * _811)))), float3(0.0))) * _950) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1108 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1110), float3(0.0), float3(1.0))) * _950) + (_989 * ((((fma(_1195, _1191, 2.0) * pow(fast::max(fma(-_1122, _1122, 1.0), 0.0), 0.5 * (_1195 * _1191))) * 0.15915493667125701904296875) * (_1110 * (_1195 * _1202))) * _955))) * (float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1058 * _1058) / fast::max(_1044, 9.9999997473787516355514526367188e-05)) * _1077) * _1077)), float3(65504.0));
    float3 _1265 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1268 = dot(_1265, _1265);
    float3 _1273 = _1265 * rsqrt(fast::max(_1268, 9.9999999392252902907785028219223e-09));
    float _1277 = _1268 * float(frame.punctualLights[1].positionFalloff.w);
    float _1282 = fast::clamp(fma(-_1277, _1277, 1.0), 0.0, 1.0);
    float _1301 = fast::clamp(fma(dot(-_1273, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1332 = dot(_667, _1273);
    float _1334 = fast::clamp(_1332, 0.0, 1.0);
    float _1346 = fast::clamp(dot(_667, fast::normalize(_673 + _1273)), 0.0, 1.0);
    float _1415 = 8192.0 * fma(-_1334, _930, _1334 + _930);
    float _1419 = 1.0 / (params.facet_alpha * _1415);
    out.fragColor = float4(_1230 + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_1332 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_1334), float3(0.0), float3(1.0))) * _950) + (_989 * ((((fma(_1419, _1415, 2.0) * pow(fast::max(fma(-_1346, _1346, 1.0), 0.0), 0.5 * (_1419 * _1415))) * 0.15915493667125701904296875) * (_1334 * (_1419 * _1202))) * _955))) * (float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1282 * _1282) / fast::max(_1268, 9.9999997473787516355514526367188e-05)) * _1301) * _1301)), float3(65504.0)), 1.0);
    return out;
}

