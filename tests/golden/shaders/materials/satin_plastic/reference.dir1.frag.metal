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
    float3 _875 = fast::normalize(in.v_normal);
    float3 _879 = fast::normalize(in.v_toEye);
    float _1009 = _875.y;
    float _1014 = _875.z;
    float _1019 = _875.x;
    float _1137 = fast::max(dot(_875, _879), 9.9999997473787516355514526367188e-05);
    float3 _1141 = reflect(-_879, _875);
    float4 _1176 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1137, params.facet_perceptualRoughness), level(0.0));
    float3 _1195 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1176.y) - 1.0));
    float _1279 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1236 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1137, _1279), level(0.0));
    float3 _1286 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1249 = _1236.z;
    float _1251 = fma(-fast::max(_1286.x, fast::max(_1286.y, _1286.z)), _1249, 1.0);
    float _1295 = _1279 * _1279;
    float3 _1272 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _1009)) + (frame.sh[2].xyz * _1014)) + (frame.sh[3].xyz * _1019)) + (((((frame.sh[4].xyz * (_1019 * _1009)) + (frame.sh[5].xyz * (_1009 * _1014))) + (frame.sh[6].xyz * fma(3.0 * _1014, _1014, -1.0))) + (frame.sh[7].xyz * (_1019 * _1014))) + (frame.sh[8].xyz * fma(_1019, _1019, -(_1009 * _1009)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1141, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1176.xxx, _1176.yyy, float3(params.facet_f0)) * _1195)) * _1251;
    float3 _1431 = fast::normalize(_879 + frame.lightDirection.xyz);
    float _1364 = fast::clamp(dot(_875, frame.lightDirection.xyz), 0.0, 1.0);
    float _1368 = fast::clamp(dot(_875, _1431), 0.0, 1.0);
    float4 _1493 = float4(cross(_875, _1431), params.facet_alpha * _1368) * 64.0;
    float _1475 = (4096.0 * params.facet_alpha) / dot(_1493, _1493);
    float _1504 = params.facet_alpha * params.facet_alpha;
    float _1510 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1537 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1431), 0.0, 1.0);
    float _1540 = _1537 * _1537;
    float _1581 = 8192.0 * fma(-_1364, _1137, _1364 + _1137);
    float _1585 = 1.0 / (_1295 * _1581);
    float3 _1620 = fma(facet_environment.sample(facet_environmentSmplr, _1141, level(_1279 * 4.0)).xyz, _1286 * _1249, _1272) + fast::min(fma(fma((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1540 * _1540) * _1537))) * (((_1475 * _1475) * 0.3183098733425140380859375) * (0.5 / fma(_1364, sqrt(fma(_1137 * _1137, _1510, _1504)), _1137 * sqrt(fma(_1364 * _1364, _1510, _1504))))), _1195, float3(params.facet_diffuseColor) * 0.3183098733425140380859375), (frame.lightColor.xyz * _1364) * _1251, (_1286 * ((((fma(_1585, _1581, 2.0) * pow(fast::max(fma(-_1368, _1368, 1.0), 0.0), 0.5 * (_1585 * _1581))) * 0.15915493667125701904296875) * (_1364 * (_1585 * (2048.0 * _1295)))) * _1236.w)) * frame.lightColor.xyz), float3(65504.0));
    out.fragColor = float4(_1620, 1.0);
    return out;
}

