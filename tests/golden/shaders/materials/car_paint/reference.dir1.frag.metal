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
    float3 _856 = fast::normalize(in.v_normal);
    float3 _860 = fast::normalize(in.v_toEye);
    float _1127 = fast::max(dot(_856, _860), 9.9999997473787516355514526367188e-05);
    float3 _1131 = reflect(-_860, _856);
    float4 _1166 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1127, params.facet_perceptualRoughness), level(0.0));
    float3 _1185 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1166.y) - 1.0));
    float _1245 = 1.0 - _1127;
    float _1248 = _1245 * _1245;
    float _1255 = fma(0.959999978542327880859375, (_1248 * _1248) * _1245, 0.039999999105930328369140625);
    float _1260 = fast::clamp(params.coat, 0.0, 1.0);
    float _1265 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1401 = fast::normalize(_860 + frame.lightDirection.xyz);
    float _1335 = fast::clamp(dot(_856, frame.lightDirection.xyz), 0.0, 1.0);
    float _1339 = fast::clamp(dot(_856, _1401), 0.0, 1.0);
    float _1343 = fast::clamp(dot(frame.lightDirection.xyz, _1401), 0.0, 1.0);
    float3 _1439 = cross(_856, _1401);
    float _1442 = _1339 * params.facet_alpha;
    float _1446 = dot(_1439, _1439);
    float _1451 = params.facet_alpha / fma(_1442, _1442, _1446);
    float _1464 = params.facet_alpha * params.facet_alpha;
    float _1470 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1497 = 1.0 - _1343;
    float _1500 = _1497 * _1497;
    float _1505 = (_1500 * _1500) * _1497;
    float3 _1361 = frame.lightColor.xyz * _1335;
    float _1542 = _1265 * _1265;
    float _1548 = _1339 * _1542;
    float _1559 = fast::max(_1343 * _1343, 6.103515625e-05);
    float _1567 = (2048.0 * _1542) / (fma(_1548, _1548, _1446) * (_1559 * 25735.927734375));
    float3 _1629 = mix(facet_environment.sample(facet_environmentSmplr, _1131, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1166.xxx, _1166.yyy, float3(params.facet_f0)) * _1185), facet_environment.sample(facet_environmentSmplr, _1131, level(_1265 * (4.0 * (2.0 - _1265)))).xyz, float3(_1255 * _1260)) + fast::min(fma(((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * _1505)) * (((_1451 * _1451) * 0.3183098733425140380859375) * (0.5 / fma(_1335, sqrt(fma(_1127 * _1127, _1470, _1464)), _1127 * sqrt(fma(_1335 * _1335, _1470, _1464)))))) * _1185, _1361 * fma(-_1255, _1260, 1.0), _1361 * ((_1567 * (_1567 * (12.56637096405029296875 * _1559))) * (fma(0.959999978542327880859375, _1505, 0.039999999105930328369140625) * _1260))), float3(65504.0));
    out.fragColor = float4(_1629, 1.0);
    return out;
}

