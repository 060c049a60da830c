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
    float3 _770 = fast::normalize(in.v_normal);
    float3 _776 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _910 = _770.y;
    float _915 = _770.z;
    float _920 = _770.x;
    float _1038 = fast::max(dot(_770, _776), 9.9999997473787516355514526367188e-05);
    float4 _1077 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1038, params.facet_perceptualRoughness), level(0.0));
    float3 _1096 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1077.y) - 1.0));
    float3 _1147 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1150 = dot(_1147, _1147);
    float3 _1155 = _1147 * rsqrt(fast::max(_1150, 9.9999999392252902907785028219223e-09));
    float _1159 = _1150 * float(frame.punctualLights[0].positionFalloff.w);
    float _1164 = fast::clamp(fma(-_1159, _1159, 1.0), 0.0, 1.0);
    float _1183 = fast::clamp(fma(dot(-_1155, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1298 = fast::normalize(_776 + _1155);
    float _1243 = fast::clamp(dot(_770, _1155), 0.0, 1.0);
    float _1336 = 4096.0 * params.facet_alpha;
    float4 _1360 = float4(cross(_770, _1298), params.facet_alpha * fast::clamp(dot(_770, _1298), 0.0, 1.0)) * 64.0;
    float _1342 = _1336 / dot(_1360, _1360);
    float _1371 = params.facet_alpha * params.facet_alpha;
    float _1377 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1381 = sqrt(fma(_1038 * _1038, _1377, _1371));
    float _1404 = 1.0 - fast::clamp(dot(_1155, _1298), 0.0, 1.0);
    float _1407 = _1404 * _1404;
    float3 _1415 = float3(1.0) - float3(params.facet_f0);
    float3 _1274 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1429 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _910)) + (frame.sh[2].xyz * _915)) + (frame.sh[3].xyz * _920)) + (((((frame.sh[4].xyz * (_920 * _910)) + (frame.sh[5].xyz * (_910 * _915))) + (frame.sh[6].xyz * fma(3.0 * _915, _915, -1.0))) + (frame.sh[7].xyz * (_920 * _915))) + (frame.sh[8].xyz * fma(_920, _920, -(_910 * _910)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_776, _770), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1077.xxx, _1077.yyy, float3(params.facet_f0)) * _1096)) + fast::min(fma((float3(params.facet_f0) + (_1415 * ((_1407 * _1407) * _1404))) * (((_1342 * _1342) * 0.3183098733425140380859375) * (0.5 / fma(_1243, _1381, _1038 * sqrt(fma(_1243 * _1243, _1377, _1371))))), _1096, _1274) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1164 * _1164) / fast::max(_1150, 9.9999997473787516355514526367188e-05)) * _1183) * _1183)) * _1243), float3(65504.0));
    float3 _1464 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1467 = dot(_1464, _1464);
    float3 _1472 = _1464 * rsqrt(fast::max(_1467, 9.9999999392252902907785028219223e-09));
    float _1476 = _1467 * float(frame.punctualLights[1].positionFalloff.w);
    float _1481 = fast::clamp(fma(-_1476, _1476, 1.0), 0.0, 1.0);
    float _1500 = fast::clamp(fma(dot(-_1472, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1615 = fast::normalize(_776 + _1472);
    float _1560 = fast::clamp(dot(_770, _1472), 0.0, 1.0);
    float4 _1677 = float4(cross(_770, _1615), params.facet_alpha * fast::clamp(dot(_770, _1615), 0.0, 1.0)) * 64.0;
    float _1659 = _1336 / dot(_1677, _1677);
    float _1721 = 1.0 - fast::clamp(dot(_1472, _1615), 0.0, 1.0);
    float _1724 = _1721 * _1721;
    out.fragColor = float4(_1429 + fast::min(fma((float3(params.facet_f0) + (_1415 * ((_1724 * _1724) * _1721))) * (((_1659 * _1659) * 0.3183098733425140380859375) * (0.5 / fma(_1560, _1381, _1038 * sqrt(fma(_1560 * _1560, _1377, _1371))))), _1096, _1274) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1481 * _1481) / fast::max(_1467, 9.9999997473787516355514526367188e-05)) * _1500) * _1500)) * _1560), float3(65504.0)), 1.0);
    return out;
}

