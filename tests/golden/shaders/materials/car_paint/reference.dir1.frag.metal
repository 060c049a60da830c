#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
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
    float3 _850 = fast::normalize(in.v_normal);
    float3 _854 = fast::normalize(in.v_toEye);
    float _1121 = fast::max(dot(_850, _854), 9.9999997473787516355514526367188e-05);
    float3 _1125 = reflect(-_854, _850);
    float4 _1160 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1121, params.facet_perceptualRoughness), level(0.0));
    float3 _1179 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1160.y) - 1.0));
    float _1234 = 1.0 - _1121;
    float _1237 = _1234 * _1234;
    float _1244 = fma(0.959999978542327880859375, (_1237 * _1237) * _1234, 0.039999999105930328369140625);
    float _1249 = fast::clamp(params.coat, 0.0, 1.0);
    float _1254 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1385 = fast::normalize(_854 + frame.lightDirection.xyz);
    float _1319 = fast::clamp(dot(_850, frame.lightDirection.xyz), 0.0, 1.0);
    float _1323 = fast::clamp(dot(_850, _1385), 0.0, 1.0);
    float _1327 = fast::clamp(dot(frame.lightDirection.xyz, _1385), 0.0, 1.0);
    float3 _1423 = cross(_850, _1385);
    float _1426 = _1323 * params.facet_alpha;
    float _1430 = dot(_1423, _1423);
    float _1435 = params.facet_alpha / fma(_1426, _1426, _1430);
    float _1448 = params.facet_alpha * params.facet_alpha;
    float _1454 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1481 = 1.0 - _1327;
    float _1484 = _1481 * _1481;
    float _1489 = (_1484 * _1484) * _1481;
    float3 _1345 = frame.lightColor.xyz * _1319;
    float _1526 = _1254 * _1254;
    float _1532 = _1323 * _1526;
    float _1543 = fast::max(_1327 * _1327, 6.103515625e-05);
    float _1551 = (2048.0 * _1526) / (fma(_1532, _1532, _1430) * (_1543 * 25735.927734375));
    out.fragColor = float4(mix(facet_environment.sample(facet_environmentSmplr, _1125, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1160.xxx, _1160.yyy, float3(params.facet_f0)) * _1179), facet_environment.sample(facet_environmentSmplr, _1125, level(_1254 * 4.0)).xyz, float3(_1244 * _1249)) + fast::min(fma(((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * _1489)) * (((_1435 * _1435) * 0.3183098733425140380859375) * (0.5 / fma(_1319, sqrt(fma(_1121 * _1121, _1454, _1448)), _1121 * sqrt(fma(_1319 * _1319, _1454, _1448)))))) * _1179, _1345 * fma(-_1244, _1249, 1.0), _1345 * ((_1551 * (_1551 * (12.56637096405029296875 * _1543))) * (fma(0.959999978542327880859375, _1489, 0.039999999105930328369140625) * _1249))), float3(65504.0)), 1.0);
    return out;
}

