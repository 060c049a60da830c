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
    float3 _861 = fast::normalize(in.v_normal);
    float3 _865 = fast::normalize(in.v_toEye);
    float _1132 = fast::max(dot(_861, _865), 9.9999997473787516355514526367188e-05);
    float3 _1136 = reflect(-_865, _861);
    float4 _1171 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1132, params.facet_perceptualRoughness), level(0.0));
    float3 _1190 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1171.y) - 1.0));
    float _1245 = 1.0 - _1132;
    float _1248 = _1245 * _1245;
    float _1255 = fma(0.959999978542327880859375, (_1248 * _1248) * _1245, 0.039999999105930328369140625);
    float _1260 = fast::clamp(params.coat, 0.0, 1.0);
    float _1265 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1396 = fast::normalize(_865 + frame.lightDirection.xyz);
    float _1330 = fast::clamp(dot(_861, frame.lightDirection.xyz), 0.0, 1.0);
    float _1334 = fast::clamp(dot(_861, _1396), 0.0, 1.0);
    float _1338 = fast::clamp(dot(frame.lightDirection.xyz, _1396), 0.0, 1.0);
    float3 _1450 = cross(_861, _1396);
    float _1454 = _1450.x;
    float4 _1458 = float4(_1454, _1450.yz, params.facet_alpha * _1334) * 64.0;
    float _1440 = (4096.0 * params.facet_alpha) / dot(_1458, _1458);
    float _1469 = params.facet_alpha * params.facet_alpha;
    float _1475 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1502 = 1.0 - _1338;
    float _1505 = _1502 * _1502;
    float _1510 = (_1505 * _1505) * _1502;
    float3 _1356 = frame.lightColor.xyz * _1330;
    float _1549 = _1265 * _1265;
    float4 _1601 = float4(_1454, _1450.yz, _1549 * _1334) * 64.0;
    float _1559 = 12.56637096405029296875 * fast::max(_1338 * _1338, 6.103515625e-05);
    float _1565 = (4096.0 * _1549) / (dot(_1601, _1601) * _1559);
    out.fragColor = float4(mix(facet_environment.sample(facet_environmentSmplr, _1136, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1171.xxx, _1171.yyy, float3(params.facet_f0)) * _1190), facet_environment.sample(facet_environmentSmplr, _1136, level(_1265 * 4.0)).xyz, float3(_1255 * _1260)) + fast::min(fma(((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * _1510)) * (((_1440 * _1440) * 0.3183098733425140380859375) * (0.5 / fma(_1330, sqrt(fma(_1132 * _1132, _1475, _1469)), _1132 * sqrt(fma(_1330 * _1330, _1475, _1469)))))) * _1190, _1356 * fma(-_1255, _1260, 1.0), _1356 * ((_1565 * (_1565 * _1559)) * (fma(0.959999978542327880859375, _1510, 0.039999999105930328369140625) * _1260))), float3(65504.0)), 1.0);
    return out;
}

