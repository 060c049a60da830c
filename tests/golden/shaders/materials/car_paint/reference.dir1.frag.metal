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
    float3 _865 = fast::normalize(in.v_normal);
    float3 _869 = fast::normalize(in.v_toEye);
    float _1136 = fast::max(dot(_865, _869), 9.9999997473787516355514526367188e-05);
    float3 _1140 = reflect(-_869, _865);
    float4 _1175 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1136, params.facet_perceptualRoughness), level(0.0));
    float3 _1194 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1175.y) - 1.0));
    float _1252 = 1.0 - _1136;
    float _1255 = _1252 * _1252;
    float _1262 = fma(0.959999978542327880859375, (_1255 * _1255) * _1252, 0.039999999105930328369140625);
    float _1267 = fast::clamp(params.coat, 0.0, 1.0);
    float _1272 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1406 = fast::normalize(_869 + frame.lightDirection.xyz);
    float _1340 = fast::clamp(dot(_865, frame.lightDirection.xyz), 0.0, 1.0);
    float _1344 = fast::clamp(dot(_865, _1406), 0.0, 1.0);
    float _1348 = fast::clamp(dot(frame.lightDirection.xyz, _1406), 0.0, 1.0);
    float3 _1460 = cross(_865, _1406);
    float _1464 = _1460.x;
    float4 _1468 = float4(_1464, _1460.yz, params.facet_alpha * _1344) * 64.0;
    float _1450 = (4096.0 * params.facet_alpha) / dot(_1468, _1468);
    float _1479 = params.facet_alpha * params.facet_alpha;
    float _1485 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1512 = 1.0 - _1348;
    float _1515 = _1512 * _1512;
    float _1520 = (_1515 * _1515) * _1512;
    float3 _1366 = frame.lightColor.xyz * _1340;
    float _1559 = _1272 * _1272;
    float4 _1611 = float4(_1464, _1460.yz, _1559 * _1344) * 64.0;
    float _1569 = 12.56637096405029296875 * fast::max(_1348 * _1348, 6.103515625e-05);
    float _1575 = (4096.0 * _1559) / (dot(_1611, _1611) * _1569);
    float3 _1654 = mix(facet_environment.sample(facet_environmentSmplr, _1140, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1175.xxx, _1175.yyy, float3(params.facet_f0)) * _1194), facet_environment.sample(facet_environmentSmplr, _1140, level(_1272 * (4.0 * (2.0 - _1272)))).xyz, float3(_1262 * _1267)) + fast::min(fma(((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * _1520)) * (((_1450 * _1450) * 0.3183098733425140380859375) * (0.5 / fma(_1340, sqrt(fma(_1136 * _1136, _1485, _1479)), _1136 * sqrt(fma(_1340 * _1340, _1485, _1479)))))) * _1194, _1366 * fma(-_1262, _1267, 1.0), _1366 * ((_1575 * (_1575 * _1569)) * (fma(0.959999978542327880859375, _1520, 0.039999999105930328369140625) * _1267))), float3(65504.0));
    out.fragColor = float4(_1654, 1.0);
    return out;
}

