#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
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
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    float3 _856 = fast::normalize(in.v_normal);
    float3 _860 = fast::normalize(in.v_toEye);
    float _990 = _856.y;
    float _995 = _856.z;
    float _1000 = _856.x;
    float _1118 = fast::max(dot(_856, _860), 9.9999997473787516355514526367188e-05);
    float3 _1122 = reflect(-_860, _856);
    float4 _1157 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1118, params.facet_perceptualRoughness), level(0.0));
    float3 _1176 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1157.y) - 1.0));
    float _1260 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1217 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1118, _1260), level(0.0));
    float3 _1267 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1230 = _1217.z;
    float _1232 = fma(-fast::max(_1267.x, fast::max(_1267.y, _1267.z)), _1230, 1.0);
    float _1276 = _1260 * _1260;
    float3 _1253 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _990)) + (frame.sh[2].xyz * _995)) + (frame.sh[3].xyz * _1000)) + (((((frame.sh[4].xyz * (_1000 * _990)) + (frame.sh[5].xyz * (_990 * _995))) + (frame.sh[6].xyz * fma(3.0 * _995, _995, -1.0))) + (frame.sh[7].xyz * (_1000 * _995))) + (frame.sh[8].xyz * fma(_1000, _1000, -(_990 * _990)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1122, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1157.xxx, _1157.yyy, float3(params.facet_f0)) * _1176)) * _1232;
    float3 _1412 = fast::normalize(_860 + frame.lightDirection.xyz);
    float _1345 = fast::clamp(dot(_856, frame.lightDirection.xyz), 0.0, 1.0);
    float _1349 = fast::clamp(dot(_856, _1412), 0.0, 1.0);
    float3 _1450 = cross(_856, _1412);
    float _1453 = _1349 * params.facet_alpha;
    float _1462 = params.facet_alpha / fma(_1453, _1453, dot(_1450, _1450));
    float _1475 = params.facet_alpha * params.facet_alpha;
    float _1481 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1508 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1412), 0.0, 1.0);
    float _1511 = _1508 * _1508;
    float _1552 = 8192.0 * fma(-_1345, _1118, _1345 + _1118);
    float _1556 = 1.0 / (_1276 * _1552);
    float3 _1591 = fma(facet_environment.sample(facet_environmentSmplr, _1122, level(_1260 * 4.0)).xyz, _1267 * _1230, _1253) + fast::min(fma(fma((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1511 * _1511) * _1508))) * (((_1462 * _1462) * 0.3183098733425140380859375) * (0.5 / fma(_1345, sqrt(fma(_1118 * _1118, _1481, _1475)), _1118 * sqrt(fma(_1345 * _1345, _1481, _1475))))), _1176, float3(params.facet_diffuseColor) * 0.3183098733425140380859375), (frame.lightColor.xyz * _1345) * _1232, (_1267 * ((((fma(_1556, _1552, 2.0) * pow(fast::max(fma(-_1349, _1349, 1.0), 0.0), 0.5 * (_1556 * _1552))) * 0.15915493667125701904296875) * (_1345 * (_1556 * (2048.0 * _1276)))) * _1217.w)) * frame.lightColor.xyz), float3(65504.0));
    out.fragColor = float4(_1591, 1.0);
    return out;
}

