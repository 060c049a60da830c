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
    float3 _868 = fast::normalize(in.v_normal);
    float3 _872 = fast::normalize(in.v_toEye);
    float _1139 = fast::max(dot(_868, _872), 9.9999997473787516355514526367188e-05);
    float3 _1143 = reflect(-_872, _868);
    float4 _1178 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1139, params.facet_perceptualRoughness), level(0.0));
    float3 _1197 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1178.y) - 1.0));
    float _1255 = 1.0 - _1139;
    float _1258 = _1255 * _1255;
    float _1265 = fma(0.959999978542327880859375, (_1258 * _1258) * _1255, 0.039999999105930328369140625);
    float _1270 = fast::clamp(params.coat, 0.0, 1.0);
    float _1275 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1409 = fast::normalize(_872 + frame.lightDirection.xyz);
    float _1342 = fast::clamp(dot(_868, frame.lightDirection.xyz), 0.0, 1.0);
    float _1346 = fast::clamp(dot(_868, _1409), 0.0, 1.0);
    float _1350 = fast::clamp(dot(frame.lightDirection.xyz, _1409), 0.0, 1.0);
    float3 _1465 = cross(_868, _1409) * 64.0;
    float _1469 = (64.0 * params.facet_alpha) * _1346;
    float _1472 = dot(_1465, _1465);
    float _1453 = (4096.0 * params.facet_alpha) / fma(_1469, _1469, _1472);
    float _1484 = params.facet_alpha * params.facet_alpha;
    float _1490 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1517 = 1.0 - _1350;
    float _1520 = _1517 * _1517;
    float _1525 = (_1520 * _1520) * _1517;
    float _1560 = _1275 * _1275;
    float _1618 = (64.0 * _1560) * _1346;
    float _1570 = 12.56637096405029296875 * fast::max(_1350 * _1350, 6.103515625e-05);
    float _1576 = (4096.0 * _1560) / (fma(_1618, _1618, _1472) * _1570);
    float3 _1649 = mix(facet_environment.sample(facet_environmentSmplr, _1143, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1178.xxx, _1178.yyy, float3(params.facet_f0)) * _1197), facet_environment.sample(facet_environmentSmplr, _1143, level(_1275 * (4.0 * (2.0 - _1275)))).xyz, float3(_1265 * _1270)) + fast::min(fast::min(((((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * _1525)) * (((_1453 * _1453) * 0.3183098733425140380859375) * (0.5 / fma(_1342, sqrt(fma(_1139 * _1139, _1490, _1484)), _1139 * sqrt(fma(_1342 * _1342, _1490, _1484)))))) * _1197) * fma(-_1265, _1270, 1.0)) + float3((_1576 * (_1576 * _1570)) * fma(0.039999999105930328369140625, _1270, (0.959999978542327880859375 * _1270) * _1525)), float3(65504.0)) * (frame.lightColor.xyz * _1342), float3(65504.0));
    out.fragColor = float4(_1649, 1.0);
    return out;
}

