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
    float3 _835 = fast::normalize(in.v_normal);
    float3 _839 = fast::normalize(in.v_toEye);
    float _1109 = fast::max(dot(_835, _839), 9.9999997473787516355514526367188e-05);
    float3 _1113 = reflect(-_839, _835);
    float4 _1148 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1109, params.facet_perceptualRoughness), level(0.0));
    float3 _1167 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1148.y) - 1.0));
    float _1222 = 1.0 - _1109;
    float _1225 = _1222 * _1222;
    float _1232 = fma(0.959999978542327880859375, (_1225 * _1225) * _1222, 0.039999999105930328369140625);
    float _1237 = fast::clamp(params.coat, 0.0, 1.0);
    float _1242 = fast::clamp(params.coatRoughness, 0.08900000154972076416015625, 1.0);
    float3 _1373 = fast::normalize(_839 + frame.lightDirection.xyz);
    float _1307 = fast::clamp(dot(_835, frame.lightDirection.xyz), 0.0, 1.0);
    float _1311 = fast::clamp(dot(_835, _1373), 0.0, 1.0);
    float _1315 = fast::clamp(dot(frame.lightDirection.xyz, _1373), 0.0, 1.0);
    float3 _1411 = cross(_835, _1373);
    float _1414 = _1311 * params.facet_alpha;
    float _1418 = dot(_1411, _1411);
    float _1423 = params.facet_alpha / fma(_1414, _1414, _1418);
    float _1436 = params.facet_alpha * params.facet_alpha;
    float _1442 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1469 = 1.0 - _1315;
    float _1472 = _1469 * _1469;
    float _1477 = (_1472 * _1472) * _1469;
    float3 _1333 = frame.lightColor.xyz * _1307;
    float _1518 = _1242 * _1242;
    float _1570 = _1311 * _1518;
    float _1579 = _1518 / fma(_1570, _1570, _1418);
    float3 _1610 = mix(facet_environment.sample(facet_environmentSmplr, _1113, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_1148.xxx, _1148.yyy, float3(params.facet_f0)) * _1167), facet_environment.sample(facet_environmentSmplr, _1113, level(_1242 * 4.0)).xyz, float3(_1232 * _1237)) + fast::min(fma(((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * _1477)) * (((_1423 * _1423) * 0.3183098733425140380859375) * (0.5 / fma(_1307, sqrt(fma(_1109 * _1109, _1442, _1436)), _1109 * sqrt(fma(_1307 * _1307, _1442, _1436)))))) * _1167, _1333 * fma(-_1232, _1237, 1.0), _1333 * ((((_1579 * _1579) * 0.3183098733425140380859375) * (0.25 / fast::max(_1315 * _1315, 6.103515625e-05))) * (fma(0.959999978542327880859375, _1477, 0.039999999105930328369140625) * _1237))), float3(65504.0));
    out.fragColor = float4(_1610, 1.0);
    return out;
}

