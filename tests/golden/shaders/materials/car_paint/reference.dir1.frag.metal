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
    float facet_clearCoat;
    float facet_clearCoatAlpha;
    float facet_clearCoatLod;
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
    float _1133 = fast::max(dot(_861, _865), 9.9999997473787516355514526367188e-05);
    float3 _1137 = reflect(-_865, _861);
    float4 _1172 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1133, params.facet_perceptualRoughness), level(0.0));
    float3 _1191 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1172.y) - 1.0));
    float _1248 = 1.0 - _1133;
    float _1251 = _1248 * _1248;
    float _1258 = fma(0.959999978542327880859375, (_1251 * _1251) * _1248, 0.039999999105930328369140625);
    float3 _1385 = fast::normalize(_865 + frame.lightDirection.xyz);
    float _1318 = fast::clamp(dot(_861, frame.lightDirection.xyz), 0.0, 1.0);
    float _1322 = fast::clamp(dot(_861, _1385), 0.0, 1.0);
    float _1326 = fast::clamp(dot(frame.lightDirection.xyz, _1385), 0.0, 1.0);
    float3 _1441 = cross(_861, _1385) * 64.0;
    float _1445 = (64.0 * params.facet_alpha) * _1322;
    float _1448 = dot(_1441, _1441);
    float _1429 = (4096.0 * params.facet_alpha) / fma(_1445, _1445, _1448);
    float _1460 = params.facet_alpha * params.facet_alpha;
    float _1466 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1493 = 1.0 - _1326;
    float _1496 = _1493 * _1493;
    float _1501 = (_1496 * _1496) * _1493;
    float _1589 = (64.0 * params.facet_clearCoatAlpha) * _1322;
    float _1542 = 12.56637096405029296875 * fast::max(_1326 * _1326, 6.103515625e-05);
    float _1548 = (4096.0 * params.facet_clearCoatAlpha) / (fma(_1589, _1589, _1448) * _1542);
    float3 _1619 = mix(facet_environment.sample(facet_environmentSmplr, _1137, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1172.xxx, _1172.yyy, float3(params.facet_f0)) * _1191), facet_environment.sample(facet_environmentSmplr, _1137, level(params.facet_clearCoatLod)).xyz, float3(_1258 * params.facet_clearCoat)) + fast::min(fast::min(((((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * _1501)) * (((_1429 * _1429) * 0.3183098733425140380859375) * (0.5 / fma(_1318, sqrt(fma(_1133 * _1133, _1466, _1460)), _1133 * sqrt(fma(_1318 * _1318, _1466, _1460)))))) * _1191) * fma(-_1258, params.facet_clearCoat, 1.0)) + float3((_1548 * (_1548 * _1542)) * fma(0.039999999105930328369140625, params.facet_clearCoat, (0.959999978542327880859375 * params.facet_clearCoat) * _1501)), float3(65504.0)) * (frame.lightColor.xyz * _1318), float3(65504.0));
    out.fragColor = float4(_1619, 1.0);
    return out;
}

