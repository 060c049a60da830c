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
    float3 _758 = fast::normalize(in.v_normal);
    float3 _764 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _898 = _758.y;
    float _903 = _758.z;
    float _908 = _758.x;
    float _1026 = fast::max(dot(_758, _764), 9.9999997473787516355514526367188e-05);
    float4 _1065 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1026, params.facet_perceptualRoughness), level(0.0));
    float3 _1084 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1065.y) - 1.0));
    float3 _1140 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1143 = dot(_1140, _1140);
    float3 _1148 = _1140 * rsqrt(fast::max(_1143, 9.9999999392252902907785028219223e-09));
    float _1152 = _1143 * float(frame.punctualLights[0].positionFalloff.w);
    float _1157 = fast::clamp(fma(-_1152, _1152, 1.0), 0.0, 1.0);
    float _1176 = fast::clamp(fma(dot(-_1148, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1291 = fast::normalize(_764 + _1148);
    float _1236 = fast::clamp(dot(_758, _1148), 0.0, 1.0);
    float3 _1329 = cross(_758, _1291);
    float _1332 = fast::clamp(dot(_758, _1291), 0.0, 1.0) * params.facet_alpha;
    float _1341 = params.facet_alpha / fma(_1332, _1332, dot(_1329, _1329));
    float _1354 = params.facet_alpha * params.facet_alpha;
    float _1360 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1364 = sqrt(fma(_1026 * _1026, _1360, _1354));
    float _1387 = 1.0 - fast::clamp(dot(_1148, _1291), 0.0, 1.0);
    float _1390 = _1387 * _1387;
    float3 _1398 = float3(1.0) - float3(params.facet_f0);
    float3 _1267 = float3(params.facet_diffuseColor) * 0.3183098733425140380859375;
    float3 _1412 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _898)) + (frame.sh[2].xyz * _903)) + (frame.sh[3].xyz * _908)) + (((((frame.sh[4].xyz * (_908 * _898)) + (frame.sh[5].xyz * (_898 * _903))) + (frame.sh[6].xyz * fma(3.0 * _903, _903, -1.0))) + (frame.sh[7].xyz * (_908 * _903))) + (frame.sh[8].xyz * fma(_908, _908, -(_898 * _898)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_764, _758), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1065.xxx, _1065.yyy, float3(params.facet_f0)) * _1084)) + fast::min(fma((float3(params.facet_f0) + (_1398 * ((_1390 * _1390) * _1387))) * (((_1341 * _1341) * 0.3183098733425140380859375) * (0.5 / fma(_1236, _1364, _1026 * sqrt(fma(_1236 * _1236, _1360, _1354))))), _1084, _1267) * ((float3(frame.punctualLights[0].colorIntensity.xyz) * ((((_1157 * _1157) / fast::max(_1143, 9.9999997473787516355514526367188e-05)) * _1176) * _1176)) * _1236), float3(65504.0));
    float3 _1447 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1450 = dot(_1447, _1447);
    float3 _1455 = _1447 * rsqrt(fast::max(_1450, 9.9999999392252902907785028219223e-09));
    float _1459 = _1450 * float(frame.punctualLights[1].positionFalloff.w);
    float _1464 = fast::clamp(fma(-_1459, _1459, 1.0), 0.0, 1.0);
    float _1483 = fast::clamp(fma(dot(-_1455, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1598 = fast::normalize(_764 + _1455);
    float _1543 = fast::clamp(dot(_758, _1455), 0.0, 1.0);
    float3 _1636 = cross(_758, _1598);
    float _1639 = fast::clamp(dot(_758, _1598), 0.0, 1.0) * params.facet_alpha;
    float _1648 = params.facet_alpha / fma(_1639, _1639, dot(_1636, _1636));
    float _1694 = 1.0 - fast::clamp(dot(_1455, _1598), 0.0, 1.0);
    float _1697 = _1694 * _1694;
    out.fragColor = float4(_1412 + fast::min(fma((float3(params.facet_f0) + (_1398 * ((_1697 * _1697) * _1694))) * (((_1648 * _1648) * 0.3183098733425140380859375) * (0.5 / fma(_1543, _1364, _1026 * sqrt(fma(_1543 * _1543, _1360, _1354))))), _1084, _1267) * ((float3(frame.punctualLights[1].colorIntensity.xyz) * ((((_1464 * _1464) / fast::max(_1450, 9.9999997473787516355514526367188e-05)) * _1483) * _1483)) * _1543), float3(65504.0)), 1.0);
    return out;
}

