#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    float3 _859 = fast::normalize(in.v_normal);
    float3 _863 = fast::normalize(in.v_toEye);
    float _993 = _859.y;
    float _998 = _859.z;
    float _1003 = _859.x;
    float _1121 = fast::max(dot(_859, _863), 9.9999997473787516355514526367188e-05);
    float3 _1125 = reflect(-_863, _859);
    float4 _1160 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1121, params.facet_perceptualRoughness), level(0.0));
    float3 _1179 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _1160.y) - 1.0));
    float _1266 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _1223 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1121, _1266), level(0.0));
    float3 _1273 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _1236 = _1223.z;
    float _1238 = fma(-fast::max(_1273.x, fast::max(_1273.y, _1273.z)), _1236, 1.0);
    float _1282 = _1266 * _1266;
    float3 _1259 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _993)) + (frame.sh[2].xyz * _998)) + (frame.sh[3].xyz * _1003)) + (((((frame.sh[4].xyz * (_1003 * _993)) + (frame.sh[5].xyz * (_993 * _998))) + (frame.sh[6].xyz * fma(3.0 * _998, _998, -1.0))) + (frame.sh[7].xyz * (_1003 * _998))) + (frame.sh[8].xyz * fma(_1003, _1003, -(_993 * _993)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _1125, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_1160.xxx, _1160.yyy, float3(params.facet_f0)) * _1179)) * _1238;
    float3 _1421 = fast::normalize(_863 + frame.lightDirection.xyz);
    float _1354 = fast::clamp(dot(_859, frame.lightDirection.xyz), 0.0, 1.0);
    float _1358 = fast::clamp(dot(_859, _1421), 0.0, 1.0);
    float3 _1459 = cross(_859, _1421);
    float _1462 = _1358 * params.facet_alpha;
    float _1471 = params.facet_alpha / fma(_1462, _1462, dot(_1459, _1459));
    float _1484 = params.facet_alpha * params.facet_alpha;
    float _1490 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1517 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1421), 0.0, 1.0);
    float _1520 = _1517 * _1517;
    float _1561 = 8192.0 * fma(-_1354, _1121, _1354 + _1121);
    float _1565 = 1.0 / (_1282 * _1561);
    float3 _1600 = fma(facet_environment.sample(facet_environmentSmplr, _1125, level(_1266 * (4.0 * (2.0 - _1266)))).xyz, _1273 * _1236, _1259) + fast::min(fma(fma((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1520 * _1520) * _1517))) * (((_1471 * _1471) * 0.3183098733425140380859375) * (0.5 / fma(_1354, sqrt(fma(_1121 * _1121, _1490, _1484)), _1121 * sqrt(fma(_1354 * _1354, _1490, _1484))))), _1179, float3(params.facet_diffuseColor) * 0.3183098733425140380859375), (frame.lightColor.xyz * _1354) * _1238, (_1273 * ((((fma(_1565, _1561, 2.0) * pow(fast::max(fma(-_1358, _1358, 1.0), 0.0), 0.5 * (_1565 * _1561))) * 0.15915493667125701904296875) * (_1354 * (_1565 * (2048.0 * _1282)))) * _1223.w)) * frame.lightColor.xyz), float3(65504.0));
    out.fragColor = float4(_1600, 1.0);
    return out;
}

