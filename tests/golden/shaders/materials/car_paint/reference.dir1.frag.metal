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
    float3 _854 = fast::normalize(in.v_normal);
    float3 _858 = fast::normalize(in.v_toEye);
    float _1125 = fast::max(dot(_854, _858), 9.9999997473787516355514526367188e-05);
    float3 _1129 = reflect(-_858, _854);
    float4 _1164 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1125, params.facet_perceptualRoughness), level(0.0));
    float3 _1183 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1164.y) - 1.0));
    float _1241 = 1.0 - _1125;
    float _1244 = _1241 * _1241;
    float _1251 = fma(0.959999978542327880859375, (_1244 * _1244) * _1241, 0.039999999105930328369140625);
    float _1256 = fast::clamp(params.coat, 0.0, 1.0);
    float _1261 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1395 = fast::normalize(_858 + frame.lightDirection.xyz);
    float _1329 = fast::clamp(dot(_854, frame.lightDirection.xyz), 0.0, 1.0);
    float _1333 = fast::clamp(dot(_854, _1395), 0.0, 1.0);
    float _1337 = fast::clamp(dot(frame.lightDirection.xyz, _1395), 0.0, 1.0);
    float3 _1433 = cross(_854, _1395);
    float _1436 = _1333 * params.facet_alpha;
    float _1440 = dot(_1433, _1433);
    float _1445 = params.facet_alpha / fma(_1436, _1436, _1440);
    float _1458 = params.facet_alpha * params.facet_alpha;
    float _1464 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1491 = 1.0 - _1337;
    float _1494 = _1491 * _1491;
    float _1499 = (_1494 * _1494) * _1491;
    float3 _1355 = frame.lightColor.xyz * _1329;
    float _1536 = _1261 * _1261;
    float _1542 = _1333 * _1536;
    float _1553 = fast::max(_1337 * _1337, 6.103515625e-05);
    float _1561 = (2048.0 * _1536) / (fma(_1542, _1542, _1440) * (_1553 * 25735.927734375));
    float3 _1623 = mix(facet_environment.sample(facet_environmentSmplr, _1129, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1164.xxx, _1164.yyy, float3(params.facet_f0)) * _1183), facet_environment.sample(facet_environmentSmplr, _1129, level(_1261 * (4.0 * (2.0 - _1261)))).xyz, float3(_1251 * _1256)) + fast::min(fma(((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * _1499)) * (((_1445 * _1445) * 0.3183098733425140380859375) * (0.5 / fma(_1329, sqrt(fma(_1125 * _1125, _1464, _1458)), _1125 * sqrt(fma(_1329 * _1329, _1464, _1458)))))) * _1183, _1355 * fma(-_1251, _1256, 1.0), _1355 * ((_1561 * (_1561 * (12.56637096405029296875 * _1553))) * (fma(0.959999978542327880859375, _1499, 0.039999999105930328369140625) * _1256))), float3(65504.0));
    out.fragColor = float4(_1623, 1.0);
    return out;
}

