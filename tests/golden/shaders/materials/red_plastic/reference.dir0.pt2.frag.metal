#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    float3 _774 = fast::normalize(in.v_normal);
    float3 _780 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _914 = _774.y;
    float _919 = _774.z;
    float _924 = _774.x;
    float _1042 = fast::max(dot(_774, _780), 9.9999997473787516355514526367188e-05);
    float4 _1081 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1042, params.facet_perceptualRoughness), level(0.0));
    float3 _1100 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1081.y) - 1.0));
    float3 _1151 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1154 = dot(_1151, _1151);
    float3 _1159 = _1151 * rsqrt(fast::max(_1154, 9.9999999392252902907785028219223e-09));
    float _1163 = _1154 * float(frame.punctualLights[0].positionFalloff.w);
    float _1168 = fast::clamp(fma(-_1163, _1163, 1.0), 0.0, 1.0);
    float _1187 = fast::clamp(fma(dot(-_1159, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1302 = fast::normalize(_780 + _1159);
    float _1247 = fast::clamp(dot(_774, _1159), 0.0, 1.0);
    float _1341 = 4096.0 * params.facet_alpha;
    float3 _1360 = cross(_774, _1302) * 64.0;
    float _1363 = 64.0 * params.facet_alpha;
    float _1364 = fast::clamp(dot(_774, _1302), 0.0, 1.0) * _1363;
    float _1347 = _1341 / fma(_1364, _1364, dot(_1360, _1360));
    float _1379 = params.facet_alpha * params.facet_alpha;
    float _1385 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1389 = sqrt(fma(_1042 * _1042, _1385, _1379));
    float _1412 = 1.0 - fast::clamp(dot(_1159, _1302), 0.0, 1.0);
    float _1415 = _1412 * _1412;
    float3 _1423 = float3(1.0) - float3(params.facet_f0);
    float3 _1278 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1437 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _914)) + (frame.sh[2].xyz * _919)) + (frame.sh[3].xyz * _924)) + (((((frame.sh[4].xyz * (_924 * _914)) + (frame.sh[5].xyz * (_914 * _919))) + (frame.sh[6].xyz * fma(3.0 * _919, _919, -1.0))) + (frame.sh[7].xyz * (_924 * _919))) + (frame.sh[8].xyz * fma(_924, _924, -(_914 * _914)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_780, _774), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1081.xxx, _1081.yyy, float3(params.facet_f0)) * _1100)) + fast::min(fma((float3(params.facet_f0) + (_1423 * ((_1415 * _1415) * _1412))) * (((_1347 * _1347) * 0.3183098733425140380859375) * (0.5 / fma(_1247, _1389, _1042 * sqrt(fma(_1247 * _1247, _1385, _1379))))), _1100, _1278) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1168 * _1168) / fast::max(_1154, 9.9999997473787516355514526367188e-05)) * _1187) * _1187)) * _1247), float3(65504.0));
    float3 _1472 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1475 = dot(_1472, _1472);
    float3 _1480 = _1472 * rsqrt(fast::max(_1475, 9.9999999392252902907785028219223e-09));
    float _1484 = _1475 * float(frame.punctualLights[1].positionFalloff.w);
    float _1489 = fast::clamp(fma(-_1484, _1484, 1.0), 0.0, 1.0);
    float _1508 = fast::clamp(fma(dot(-_1480, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1623 = fast::normalize(_780 + _1480);
    float _1568 = fast::clamp(dot(_774, _1480), 0.0, 1.0);
    float3 _1681 = cross(_774, _1623) * 64.0;
    float _1685 = fast::clamp(dot(_774, _1623), 0.0, 1.0) * _1363;
    float _1668 = _1341 / fma(_1685, _1685, dot(_1681, _1681));
    float _1733 = 1.0 - fast::clamp(dot(_1480, _1623), 0.0, 1.0);
    float _1736 = _1733 * _1733;
    out.fragColor = float4(_1437 + fast::min(fma((float3(params.facet_f0) + (_1423 * ((_1736 * _1736) * _1733))) * (((_1668 * _1668) * 0.3183098733425140380859375) * (0.5 / fma(_1568, _1389, _1042 * sqrt(fma(_1568 * _1568, _1385, _1379))))), _1100, _1278) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1489 * _1489) / fast::max(_1475, 9.9999997473787516355514526367188e-05)) * _1508) * _1508)) * _1568), float3(65504.0)), 1.0);
    return out;
}

