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
    float3 _852 = fast::normalize(in.v_normal);
    float3 _856 = fast::normalize(in.v_toEye);
    float _1123 = fast::max(dot(_852, _856), 9.9999997473787516355514526367188e-05);
    float3 _1127 = reflect(-_856, _852);
    float4 _1162 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1123, params.facet_perceptualRoughness), level(0.0));
    float3 _1181 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1162.y) - 1.0));
    float _1236 = 1.0 - _1123;
    float _1239 = _1236 * _1236;
    float _1246 = fma(0.959999978542327880859375, (_1239 * _1239) * _1236, 0.039999999105930328369140625);
    float _1251 = fast::clamp(params.coat, 0.0, 1.0);
    float _1256 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1387 = fast::normalize(_856 + frame.lightDirection.xyz);
    float _1321 = fast::clamp(dot(_852, frame.lightDirection.xyz), 0.0, 1.0);
    float _1325 = fast::clamp(dot(_852, _1387), 0.0, 1.0);
    float _1329 = fast::clamp(dot(frame.lightDirection.xyz, _1387), 0.0, 1.0);
    float3 _1425 = cross(_852, _1387);
    float _1428 = _1325 * params.facet_alpha;
    float _1437 = params.facet_alpha / fma(_1428, _1428, dot(_1425, _1425));
    float _1450 = params.facet_alpha * params.facet_alpha;
    float _1456 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1483 = 1.0 - _1329;
    float _1486 = _1483 * _1483;
    float _1491 = (_1486 * _1486) * _1483;
    float3 _1347 = frame.lightColor.xyz * _1321;
    float _1528 = _1256 * _1256;
    float3 _1532 = _1425 * 64.0;
    float _1536 = _1325 * (64.0 * _1528);
    float _1548 = 12.56637096405029296875 * fast::max(_1329 * _1329, 6.103515625e-05);
    float _1554 = (4096.0 * _1528) / (fma(_1536, _1536, dot(_1532, _1532)) * _1548);
    out.fragColor = float4(mix(facet_environment.sample(facet_environmentSmplr, _1127, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1162.xxx, _1162.yyy, float3(params.facet_f0)) * _1181), facet_environment.sample(facet_environmentSmplr, _1127, level(_1256 * 4.0)).xyz, float3(_1246 * _1251)) + fast::min(fma(((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * _1491)) * (((_1437 * _1437) * 0.3183098733425140380859375) * (0.5 / fma(_1321, sqrt(fma(_1123 * _1123, _1456, _1450)), _1123 * sqrt(fma(_1321 * _1321, _1456, _1450)))))) * _1181, _1347 * fma(-_1246, _1251, 1.0), _1347 * ((_1554 * (_1554 * _1548)) * (fma(0.959999978542327880859375, _1491, 0.039999999105930328369140625) * _1251))), float3(65504.0)), 1.0);
    return out;
}

