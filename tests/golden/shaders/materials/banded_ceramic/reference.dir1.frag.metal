#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 glazeColor;
    packed_float3 clayColor;
    float glazeRoughness;
    float clayRoughness;
    float bandsPerUnit;
    float bandSharpness;
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
    float3 v_worldPosition [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    float3 _755 = fast::normalize(in.v_normal);
    float3 _762 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _868 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _917 = _755.y;
    float _922 = _755.z;
    float _927 = _755.x;
    float3 _1018 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_868)), float3(0.0), float3(1.0)) * 1.0;
    float _1093 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _868), 0.0, 1.0);
    float3 _1101 = float3((0.1599999964237213134765625 * _1093) * _1093);
    float _1110 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _868), 0.08900000154972076416015625, 1.0);
    float _1053 = fast::max(dot(_755, _762), 9.9999997473787516355514526367188e-05);
    float4 _1117 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1053, _1110), level(0.0));
    float3 _1136 = float3(1.0) + (_1101 * ((1.0 / _1117.y) - 1.0));
    float _1282 = _1110 * _1110;
    float3 _1293 = fast::normalize(_762 + frame.lightDirection.xyz);
    float _1203 = fast::clamp(dot(_755, frame.lightDirection.xyz), 0.0, 1.0);
    float4 _1355 = float4(cross(_755, _1293), _1282 * fast::clamp(dot(_755, _1293), 0.0, 1.0)) * 64.0;
    float _1337 = (4096.0 * _1282) / dot(_1355, _1355);
    float _1366 = _1282 * _1282;
    float _1372 = fma(-_1282, _1282, 1.0);
    float _1399 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1293), 0.0, 1.0);
    float _1402 = _1399 * _1399;
    float3 _1432 = fma(_1018, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _917)) + (frame.sh[2].xyz * _922)) + (frame.sh[3].xyz * _927)) + (((((frame.sh[4].xyz * (_927 * _917)) + (frame.sh[5].xyz * (_917 * _922))) + (frame.sh[6].xyz * fma(3.0 * _922, _922, -1.0))) + (frame.sh[7].xyz * (_927 * _922))) + (frame.sh[8].xyz * fma(_927, _927, -(_917 * _917)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_762, _755), level(_1110 * 4.0)).xyz * (mix(_1117.xxx, _1117.yyy, _1101) * _1136)) + fast::min(fma((_1101 + ((float3(1.0) - _1101) * ((_1402 * _1402) * _1399))) * (((_1337 * _1337) * 0.3183098733425140380859375) * (0.5 / fma(_1203, sqrt(fma(_1053 * _1053, _1372, _1366)), _1053 * sqrt(fma(_1203 * _1203, _1372, _1366))))), _1136, _1018 * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1203), float3(65504.0));
    out.fragColor = float4(_1432, 1.0);
    return out;
}

