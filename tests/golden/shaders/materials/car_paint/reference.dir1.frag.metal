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
    float _1124 = fast::max(dot(_850, _854), 9.9999997473787516355514526367188e-05);
    float3 _1128 = reflect(-_854, _850);
    float4 _1163 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1124, params.facet_perceptualRoughness), level(0.0));
    float3 _1182 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1163.y) - 1.0));
    float _1237 = 1.0 - _1124;
    float _1240 = _1237 * _1237;
    float _1247 = fma(0.959999978542327880859375, (_1240 * _1240) * _1237, 0.039999999105930328369140625);
    float _1252 = fast::clamp(params.coat, 0.0, 1.0);
    float _1257 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1388 = fast::normalize(_854 + frame.lightDirection.xyz);
    float _1322 = fast::clamp(dot(_850, frame.lightDirection.xyz), 0.0, 1.0);
    float _1326 = fast::clamp(dot(_850, _1388), 0.0, 1.0);
    float _1330 = fast::clamp(dot(frame.lightDirection.xyz, _1388), 0.0, 1.0);
    float3 _1426 = cross(_850, _1388);
    float _1429 = _1326 * params.facet_alpha;
    float _1433 = dot(_1426, _1426);
    float _1438 = params.facet_alpha / fma(_1429, _1429, _1433);
    float _1451 = params.facet_alpha * params.facet_alpha;
    float _1457 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1484 = 1.0 - _1330;
    float _1487 = _1484 * _1484;
    float _1492 = (_1487 * _1487) * _1484;
    float3 _1348 = frame.lightColor.xyz * _1322;
    float _1529 = _1257 * _1257;
    float _1535 = _1326 * _1529;
    float _1546 = fast::max(_1330 * _1330, 6.103515625e-05);
    float _1554 = (2048.0 * _1529) / (fma(_1535, _1535, _1433) * (_1546 * 25735.927734375));
    out.fragColor = float4(mix(facet_environment.sample(facet_environmentSmplr, _1128, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1163.xxx, _1163.yyy, float3(params.facet_f0)) * _1182), facet_environment.sample(facet_environmentSmplr, _1128, level(_1257 * 4.0)).xyz, float3(_1247 * _1252)) + fast::min(fma(((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * _1492)) * (((_1438 * _1438) * 0.3183098733425140380859375) * (0.5 / fma(_1322, sqrt(fma(_1124 * _1124, _1457, _1451)), _1124 * sqrt(fma(_1322 * _1322, _1457, _1451)))))) * _1182, _1348 * fma(-_1247, _1252, 1.0), _1348 * ((_1554 * (_1554 * (12.56637096405029296875 * _1546))) * (fma(0.959999978542327880859375, _1492, 0.039999999105930328369140625) * _1252))), float3(65504.0)), 1.0);
    return out;
}

