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
    float3 _864 = fast::normalize(in.v_normal);
    float3 _868 = fast::normalize(in.v_toEye);
    float _1135 = fast::max(dot(_864, _868), 9.9999997473787516355514526367188e-05);
    float3 _1139 = reflect(-_868, _864);
    float4 _1174 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1135, params.facet_perceptualRoughness), level(0.0));
    float3 _1193 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1174.y) - 1.0));
    float _1248 = 1.0 - _1135;
    float _1251 = _1248 * _1248;
    float _1258 = fma(0.959999978542327880859375, (_1251 * _1251) * _1248, 0.039999999105930328369140625);
    float _1263 = fast::clamp(params.coat, 0.0, 1.0);
    float _1268 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1399 = fast::normalize(_868 + frame.lightDirection.xyz);
    float _1333 = fast::clamp(dot(_864, frame.lightDirection.xyz), 0.0, 1.0);
    float _1337 = fast::clamp(dot(_864, _1399), 0.0, 1.0);
    float _1341 = fast::clamp(dot(frame.lightDirection.xyz, _1399), 0.0, 1.0);
    float3 _1457 = cross(_864, _1399) * 64.0;
    float _1461 = _1337 * (64.0 * params.facet_alpha);
    float _1464 = dot(_1457, _1457);
    float _1444 = (4096.0 * params.facet_alpha) / fma(_1461, _1461, _1464);
    float _1476 = params.facet_alpha * params.facet_alpha;
    float _1482 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1509 = 1.0 - _1341;
    float _1512 = _1509 * _1509;
    float _1517 = (_1512 * _1512) * _1509;
    float3 _1359 = frame.lightColor.xyz * _1333;
    float _1556 = _1268 * _1268;
    float _1606 = _1337 * (64.0 * _1556);
    float _1566 = 12.56637096405029296875 * fast::max(_1341 * _1341, 6.103515625e-05);
    float _1572 = (4096.0 * _1556) / (fma(_1606, _1606, _1464) * _1566);
    out.fragColor = float4(mix(facet_environment.sample(facet_environmentSmplr, _1139, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1174.xxx, _1174.yyy, float3(params.facet_f0)) * _1193), facet_environment.sample(facet_environmentSmplr, _1139, level(_1268 * 4.0)).xyz, float3(_1258 * _1263)) + fast::min(fma(((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * _1517)) * (((_1444 * _1444) * 0.3183098733425140380859375) * (0.5 / fma(_1333, sqrt(fma(_1135 * _1135, _1482, _1476)), _1135 * sqrt(fma(_1333 * _1333, _1482, _1476)))))) * _1193, _1359 * fma(-_1258, _1263, 1.0), _1359 * ((_1572 * (_1572 * _1566)) * (fma(0.959999978542327880859375, _1517, 0.039999999105930328369140625) * _1263))), float3(65504.0)), 1.0);
    return out;
}

