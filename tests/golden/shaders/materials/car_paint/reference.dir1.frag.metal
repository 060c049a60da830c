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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    float3 _847 = fast::normalize(in.v_normal);
    float3 _851 = fast::normalize(in.v_toEye);
    float _1117 = fast::max(dot(_847, _851), 9.9999997473787516355514526367188e-05);
    float3 _1121 = reflect(-_851, _847);
    float4 _1159 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1117, params.facet_perceptualRoughness), level(0.0));
    float3 _1178 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1159.y) - 1.0));
    float _1224 = 1.0 - _1117;
    float _1227 = _1224 * _1224;
    float _1234 = fma(0.959999978542327880859375, (_1227 * _1227) * _1224, 0.039999999105930328369140625);
    float _1291 = fast::clamp(dot(_847, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1361 = fast::normalize(_851 + frame.lightDirection.xyz);
    float _1298 = fast::clamp(dot(_847, _1361), 0.0, 1.0);
    float _1302 = fast::clamp(dot(frame.lightDirection.xyz, _1361), 0.0, 1.0);
    float3 _1417 = cross(_847, _1361) * 64.0;
    float _1421 = (64.0 * params.facet_alpha) * _1298;
    float _1424 = dot(_1417, _1417);
    float _1405 = (4096.0 * params.facet_alpha) / fma(_1421, _1421, _1424);
    float _1436 = params.facet_alpha * params.facet_alpha;
    float _1442 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1469 = 1.0 - _1302;
    float _1472 = _1469 * _1469;
    float _1477 = (_1472 * _1472) * _1469;
    float _1565 = (64.0 * params.facet_clearCoatAlpha) * _1298;
    float _1518 = 12.56637096405029296875 * fast::max(_1302 * _1302, 6.103515625e-05);
    float _1524 = (4096.0 * params.facet_clearCoatAlpha) / (fma(_1565, _1565, _1424) * _1518);
    float3 _1595 = mix(facet_environment.sample(facet_environmentSmplr, _1121, level(params.facet_environmentLod)).xyz * (mix(_1159.xxx, _1159.yyy, float3(params.facet_f0)) * _1178), facet_environment.sample(facet_environmentSmplr, _1121, level(params.facet_clearCoatLod)).xyz, float3(_1234 * params.facet_clearCoat)) + fast::min(fast::min(((((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * _1477)) * (((_1405 * _1405) * 0.3183098733425140380859375) * (0.5 / fma(_1291, sqrt(fma(_1117 * _1117, _1442, _1436)), _1117 * sqrt(fma(_1291 * _1291, _1442, _1436)))))) * _1178) * fma(-_1234, params.facet_clearCoat, 1.0)) + float3((_1524 * (_1524 * _1518)) * fma(0.039999999105930328369140625, params.facet_clearCoat, (0.959999978542327880859375 * params.facet_clearCoat) * _1477)), float3(65504.0)) * (frame.lightColor.xyz * _1291), float3(65504.0));
    out.fragColor = float4(_1595, 1.0);
    return out;
}

