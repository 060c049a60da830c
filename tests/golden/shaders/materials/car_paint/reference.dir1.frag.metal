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
    float3 _871 = fast::normalize(in.v_normal);
    float3 _875 = fast::normalize(in.v_toEye);
    float _1142 = fast::max(dot(_871, _875), 9.9999997473787516355514526367188e-05);
    float3 _1146 = reflect(-_875, _871);
    float4 _1181 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1142, params.facet_perceptualRoughness), level(0.0));
    float3 _1200 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1181.y) - 1.0));
    float _1257 = fast::clamp(params.coat, 0.0, 1.0);
    float _1263 = 1.0 - _1142;
    float _1266 = _1263 * _1263;
    float _1270 = 0.959999978542327880859375 * _1257;
    float _1277 = fma(0.039999999105930328369140625, _1257, _1270 * ((_1266 * _1266) * _1263));
    float _1282 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1416 = fast::normalize(_875 + frame.lightDirection.xyz);
    float _1350 = fast::clamp(dot(_871, frame.lightDirection.xyz), 0.0, 1.0);
    float _1354 = fast::clamp(dot(_871, _1416), 0.0, 1.0);
    float _1358 = fast::clamp(dot(frame.lightDirection.xyz, _1416), 0.0, 1.0);
    float3 _1472 = cross(_871, _1416) * 64.0;
    float _1476 = (64.0 * params.facet_alpha) * _1354;
    float _1479 = dot(_1472, _1472);
    float _1460 = (4096.0 * params.facet_alpha) / fma(_1476, _1476, _1479);
    float _1491 = params.facet_alpha * params.facet_alpha;
    float _1497 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1524 = 1.0 - _1358;
    float _1527 = _1524 * _1524;
    float _1532 = (_1527 * _1527) * _1524;
    float3 _1376 = frame.lightColor.xyz * _1350;
    float _1572 = _1282 * _1282;
    float _1621 = (64.0 * _1572) * _1354;
    float _1582 = 12.56637096405029296875 * fast::max(_1358 * _1358, 6.103515625e-05);
    float _1588 = (4096.0 * _1572) / (fma(_1621, _1621, _1479) * _1582);
    float3 _1672 = mix(facet_environment.sample(facet_environmentSmplr, _1146, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1181.xxx, _1181.yyy, float3(params.facet_f0)) * _1200), facet_environment.sample(facet_environmentSmplr, _1146, level(_1282 * (4.0 * (2.0 - _1282)))).xyz, float3(_1277)) + fast::min(fma(((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * _1532)) * (((_1460 * _1460) * 0.3183098733425140380859375) * (0.5 / fma(_1350, sqrt(fma(_1142 * _1142, _1497, _1491)), _1142 * sqrt(fma(_1350 * _1350, _1497, _1491)))))) * _1200, _1376 * (1.0 - _1277), _1376 * ((_1588 * (_1588 * _1582)) * fma(0.039999999105930328369140625, _1257, _1270 * _1532))), float3(65504.0));
    out.fragColor = float4(_1672, 1.0);
    return out;
}

