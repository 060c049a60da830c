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
    float3 _861 = fast::normalize(in.v_normal);
    float3 _865 = fast::normalize(in.v_toEye);
    float _995 = _861.y;
    float _1000 = _861.z;
    float _1005 = _861.x;
    float _1123 = fast::max(dot(_861, _865), 9.9999997473787516355514526367188e-05);
    float3 _1127 = reflect(-_865, _861);
    float4 _1162 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1123, params.facet_perceptualRoughness), level(0.0));
    float3 _1181 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1162.y) - 1.0));
    float _1270 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1227 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1123, _1270), level(0.0));
    float3 _1277 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1240 = _1227.z;
    float _1242 = fma(-fast::max(_1277.x, fast::max(_1277.y, _1277.z)), _1240, 1.0);
    float _1286 = _1270 * _1270;
    float3 _1263 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _995)) + (frame.sh[2].xyz * _1000)) + (frame.sh[3].xyz * _1005)) + (((((frame.sh[4].xyz * (_1005 * _995)) + (frame.sh[5].xyz * (_995 * _1000))) + (frame.sh[6].xyz * fma(3.0 * _1000, _1000, -1.0))) + (frame.sh[7].xyz * (_1005 * _1000))) + (frame.sh[8].xyz * fma(_1005, _1005, -(_995 * _995)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1127, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1162.xxx, _1162.yyy, float3(params.facet_f0)) * _1181)) * _1242;
    float3 _1427 = fast::normalize(_865 + frame.lightDirection.xyz);
    float _1360 = fast::clamp(dot(_861, frame.lightDirection.xyz), 0.0, 1.0);
    float _1364 = fast::clamp(dot(_861, _1427), 0.0, 1.0);
    float3 _1465 = cross(_861, _1427);
    float _1468 = _1364 * params.facet_alpha;
    float _1477 = params.facet_alpha / fma(_1468, _1468, dot(_1465, _1465));
    float _1490 = params.facet_alpha * params.facet_alpha;
    float _1496 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1523 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1427), 0.0, 1.0);
    float _1526 = _1523 * _1523;
    float _1567 = 8192.0 * fma(-_1360, _1123, _1360 + _1123);
    float _1571 = 1.0 / (_1286 * _1567);
    float3 _1606 = fma(facet_environment.sample(facet_environmentSmplr, _1127, level(_1270 * (4.0 * (2.0 - _1270)))).xyz, _1277 * _1240, _1263) + fast::min(fma(fma((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1526 * _1526) * _1523))) * (((_1477 * _1477) * 0.3183098733425140380859375) * (0.5 / fma(_1360, sqrt(fma(_1123 * _1123, _1496, _1490)), _1123 * sqrt(fma(_1360 * _1360, _1496, _1490))))), _1181, float3(params.facet_diffuseColor) * 0.3183098733425140380859375), (frame.lightColor.xyz * _1360) * _1242, (_1277 * ((((fma(_1571, _1567, 2.0) * pow(fast::max(fma(-_1364, _1364, 1.0), 0.0), 0.5 * (_1571 * _1567))) * 0.15915493667125701904296875) * (_1360 * (_1571 * (2048.0 * _1286)))) * _1227.w)) * frame.lightColor.xyz), float3(65504.0));
    out.fragColor = float4(_1606, 1.0);
    return out;
}

