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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    float3 _762 = fast::normalize(in.v_normal);
    float3 _768 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1033 = fast::max(dot(_762, _768), 9.9999997473787516355514526367188e-05);
    float4 _1075 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1033, params.facet_perceptualRoughness), level(0.0));
    float3 _1094 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1075.y) - 1.0));
    float3 _1137 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1140 = dot(_1137, _1137);
    float3 _1145 = _1137 * rsqrt(fast::max(_1140, 9.9999999392252902907785028219223e-09));
    float _1149 = _1140 * float(frame.punctualLights[0].positionFalloff.w);
    float _1154 = fast::clamp(fma(-_1149, _1149, 1.0), 0.0, 1.0);
    float _1173 = fast::clamp(fma(dot(-_1145, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float _1230 = fast::clamp(dot(_762, _1145), 0.0, 1.0);
    float3 _1288 = fast::normalize(_768 + _1145);
    float _1326 = 4096.0 * params.facet_alpha;
    float4 _1350 = float4(cross(_762, _1288), params.facet_alpha * fast::clamp(dot(_762, _1288), 0.0, 1.0)) * 64.0;
    float _1332 = _1326 / dot(_1350, _1350);
    float _1361 = params.facet_alpha * params.facet_alpha;
    float _1367 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1371 = sqrt(fma(_1033 * _1033, _1367, _1361));
    float _1394 = 1.0 - fast::clamp(dot(_1145, _1288), 0.0, 1.0);
    float _1397 = _1394 * _1394;
    float3 _1405 = float3(1.0) - float3(params.facet_f0);
    float3 _1462 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1465 = dot(_1462, _1462);
    float3 _1470 = _1462 * rsqrt(fast::max(_1465, 9.9999999392252902907785028219223e-09));
    float _1474 = _1465 * float(frame.punctualLights[1].positionFalloff.w);
    float _1479 = fast::clamp(fma(-_1474, _1474, 1.0), 0.0, 1.0);
    float _1498 = fast::clamp(fma(dot(-_1470, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float _1555 = fast::clamp(dot(_762, _1470), 0.0, 1.0);
    float3 _1613 = fast::normalize(_768 + _1470);
    float4 _1675 = float4(cross(_762, _1613), params.facet_alpha * fast::clamp(dot(_762, _1613), 0.0, 1.0)) * 64.0;
    float _1657 = _1326 / dot(_1675, _1675);
    float _1719 = 1.0 - fast::clamp(dot(_1470, _1613), 0.0, 1.0);
    float _1722 = _1719 * _1719;
    float3 _1752 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_768, _762), level(params.facet_environmentLod)).xyz, mix(_1075.xxx, _1075.yyy, float3(params.facet_f0)) * _1094, fast::min((((float3(params.facet_f0) + (_1405 * ((_1397 * _1397) * _1394))) * (((_1332 * _1332) * 0.3183098733425140380859375) * (0.5 / fma(_1230, _1371, _1033 * sqrt(fma(_1230 * _1230, _1367, _1361)))))) * _1094) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1154 * _1154) / fast::max(_1140, 9.9999997473787516355514526367188e-05)) * _1173) * _1173)) * _1230), float3(65504.0))) + fast::min((((float3(params.facet_f0) + (_1405 * ((_1722 * _1722) * _1719))) * (((_1657 * _1657) * 0.3183098733425140380859375) * (0.5 / fma(_1555, _1371, _1033 * sqrt(fma(_1555 * _1555, _1367, _1361)))))) * _1094) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1479 * _1479) / fast::max(_1465, 9.9999997473787516355514526367188e-05)) * _1498) * _1498)) * _1555), float3(65504.0));
    out.fragColor = float4(_1752, 1.0);
    return out;
}

