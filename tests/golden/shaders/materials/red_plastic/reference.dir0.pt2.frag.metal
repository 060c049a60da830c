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
    float3 _1154 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1157 = dot(_1154, _1154);
    float3 _1162 = _1154 * rsqrt(fast::max(_1157, 9.9999999392252902907785028219223e-09));
    float _1166 = _1157 * float(frame.punctualLights[0].positionFalloff.w);
    float _1171 = fast::clamp(fma(-_1166, _1166, 1.0), 0.0, 1.0);
    float _1190 = fast::clamp(fma(dot(-_1162, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1305 = fast::normalize(_780 + _1162);
    float _1250 = fast::clamp(dot(_774, _1162), 0.0, 1.0);
    float _1343 = 4096.0 * params.facet_alpha;
    float4 _1367 = float4(cross(_774, _1305), params.facet_alpha * fast::clamp(dot(_774, _1305), 0.0, 1.0)) * 64.0;
    float _1349 = _1343 / dot(_1367, _1367);
    float _1378 = params.facet_alpha * params.facet_alpha;
    float _1384 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1388 = sqrt(fma(_1042 * _1042, _1384, _1378));
    float _1411 = 1.0 - fast::clamp(dot(_1162, _1305), 0.0, 1.0);
    float _1414 = _1411 * _1411;
    float3 _1422 = float3(1.0) - float3(params.facet_f0);
    float3 _1281 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1436 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _914)) + (frame.sh[2].xyz * _919)) + (frame.sh[3].xyz * _924)) + (((((frame.sh[4].xyz * (_924 * _914)) + (frame.sh[5].xyz * (_914 * _919))) + (frame.sh[6].xyz * fma(3.0 * _919, _919, -1.0))) + (frame.sh[7].xyz * (_924 * _919))) + (frame.sh[8].xyz * fma(_924, _924, -(_914 * _914)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_780, _774), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1081.xxx, _1081.yyy, float3(params.facet_f0)) * _1100)) + fast::min(fma((float3(params.facet_f0) + (_1422 * ((_1414 * _1414) * _1411))) * (((_1349 * _1349) * 0.3183098733425140380859375) * (0.5 / fma(_1250, _1388, _1042 * sqrt(fma(_1250 * _1250, _1384, _1378))))), _1100, _1281) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1171 * _1171) / fast::max(_1157, 9.9999997473787516355514526367188e-05)) * _1190) * _1190)) * _1250), float3(65504.0));
    float3 _1471 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1474 = dot(_1471, _1471);
    float3 _1479 = _1471 * rsqrt(fast::max(_1474, 9.9999999392252902907785028219223e-09));
    float _1483 = _1474 * float(frame.punctualLights[1].positionFalloff.w);
    float _1488 = fast::clamp(fma(-_1483, _1483, 1.0), 0.0, 1.0);
    float _1507 = fast::clamp(fma(dot(-_1479, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1622 = fast::normalize(_780 + _1479);
    float _1567 = fast::clamp(dot(_774, _1479), 0.0, 1.0);
    float4 _1684 = float4(cross(_774, _1622), params.facet_alpha * fast::clamp(dot(_774, _1622), 0.0, 1.0)) * 64.0;
    float _1666 = _1343 / dot(_1684, _1684);
    float _1728 = 1.0 - fast::clamp(dot(_1479, _1622), 0.0, 1.0);
    float _1731 = _1728 * _1728;
    out.fragColor = float4(_1436 + fast::min(fma((float3(params.facet_f0) + (_1422 * ((_1731 * _1731) * _1728))) * (((_1666 * _1666) * 0.3183098733425140380859375) * (0.5 / fma(_1567, _1388, _1042 * sqrt(fma(_1567 * _1567, _1384, _1378))))), _1100, _1281) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1488 * _1488) / fast::max(_1474, 9.9999997473787516355514526367188e-05)) * _1507) * _1507)) * _1567), float3(65504.0)), 1.0);
    return out;
}

