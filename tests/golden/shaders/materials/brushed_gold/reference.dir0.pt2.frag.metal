#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float facet_perceptualRoughness;
    char _m3_pad[12];
    packed_float3 facet_f0;
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
    float3 _756 = fast::normalize(in.v_normal);
    float3 _762 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1029 = fast::max(dot(_756, _762), 9.9999997473787516355514526367188e-05);
    float4 _1068 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1029, params.facet_perceptualRoughness), level(0.0));
    float3 _1087 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1068.y) - 1.0));
    float3 _1138 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1141 = dot(_1138, _1138);
    float3 _1146 = _1138 * rsqrt(fast::max(_1141, 9.9999999392252902907785028219223e-09));
    float _1150 = _1141 * float(frame.punctualLights[0].positionFalloff.w);
    float _1155 = fast::clamp(fma(-_1150, _1150, 1.0), 0.0, 1.0);
    float _1174 = fast::clamp(fma(dot(-_1146, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1289 = fast::normalize(_762 + _1146);
    float _1234 = fast::clamp(dot(_756, _1146), 0.0, 1.0);
    float3 _1327 = cross(_756, _1289);
    float _1330 = fast::clamp(dot(_756, _1289), 0.0, 1.0) * params.facet_alpha;
    float _1339 = params.facet_alpha / fma(_1330, _1330, dot(_1327, _1327));
    float _1352 = params.facet_alpha * params.facet_alpha;
    float _1358 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1362 = sqrt(fma(_1029 * _1029, _1358, _1352));
    float _1385 = 1.0 - fast::clamp(dot(_1146, _1289), 0.0, 1.0);
    float _1388 = _1385 * _1385;
    float3 _1396 = float3(1.0) - float3(params.facet_f0);
    float3 _1453 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1456 = dot(_1453, _1453);
    float3 _1461 = _1453 * rsqrt(fast::max(_1456, 9.9999999392252902907785028219223e-09));
    float _1465 = _1456 * float(frame.punctualLights[1].positionFalloff.w);
    float _1470 = fast::clamp(fma(-_1465, _1465, 1.0), 0.0, 1.0);
    float _1489 = fast::clamp(fma(dot(-_1461, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1604 = fast::normalize(_762 + _1461);
    float _1549 = fast::clamp(dot(_756, _1461), 0.0, 1.0);
    float3 _1642 = cross(_756, _1604);
    float _1645 = fast::clamp(dot(_756, _1604), 0.0, 1.0) * params.facet_alpha;
    float _1654 = params.facet_alpha / fma(_1645, _1645, dot(_1642, _1642));
    float _1700 = 1.0 - fast::clamp(dot(_1461, _1604), 0.0, 1.0);
    float _1703 = _1700 * _1700;
    float3 _1733 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_762, _756), level(params.facet_perceptualRoughness * 4.0)).xyz, mix(_1068.xxx, _1068.yyy, float3(params.facet_f0)) * _1087, fast::min((((float3(params.facet_f0) + (_1396 * ((_1388 * _1388) * _1385))) * (((_1339 * _1339) * 0.3183098733425140380859375) * (0.5 / fma(_1234, _1362, _1029 * sqrt(fma(_1234 * _1234, _1358, _1352)))))) * _1087) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1155 * _1155) / fast::max(_1141, 9.9999997473787516355514526367188e-05)) * _1174) * _1174)) * _1234), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1396 * ((_1703 * _1703) * _1700))) * (((_1654 * _1654) * 0.3183098733425140380859375) * (0.5 / fma(_1549, _1362, _1029 * sqrt(fma(_1549 * _1549, _1358, _1352)))))) * _1087) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1470 * _1470) / fast::max(_1456, 9.9999997473787516355514526367188e-05)) * _1489) * _1489)) * _1549), float3(65504.0));
    out.fragColor = float4(_1733, 1.0);
    return out;
}

