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
    float3 _742 = fast::normalize(in.v_normal);
    float3 _749 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _855 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _904 = _742.y;
    float _909 = _742.z;
    float _914 = _742.x;
    float3 _1005 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_855)), float3(0.0), float3(1.0)) * 1.0;
    float _1080 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _855), 0.0, 1.0);
    float3 _1088 = float3((0.1599999964237213134765625 * _1080) * _1080);
    float _1097 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _855), 0.08900000154972076416015625, 1.0);
    float _1040 = fast::max(dot(_742, _749), 9.9999997473787516355514526367188e-05);
    float4 _1104 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1040, _1097), level(0.0));
    float3 _1123 = float3(1.0) + (_1088 * ((1.0 / _1104.y) - 1.0));
    float _1274 = _1097 * _1097;
    float3 _1285 = fast::normalize(_749 + frame.lightDirection.xyz);
    float _1195 = fast::clamp(dot(_742, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1323 = cross(_742, _1285);
    float _1326 = fast::clamp(dot(_742, _1285), 0.0, 1.0) * _1274;
    float _1335 = _1274 / fma(_1326, _1326, dot(_1323, _1323));
    float _1348 = _1274 * _1274;
    float _1354 = fma(-_1274, _1274, 1.0);
    float _1381 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1285), 0.0, 1.0);
    float _1384 = _1381 * _1381;
    float3 _1414 = fma(_1005, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _904)) + (frame.sh[2].xyz * _909)) + (frame.sh[3].xyz * _914)) + (((((frame.sh[4].xyz * (_914 * _904)) + (frame.sh[5].xyz * (_904 * _909))) + (frame.sh[6].xyz * fma(3.0 * _909, _909, -1.0))) + (frame.sh[7].xyz * (_914 * _909))) + (frame.sh[8].xyz * fma(_914, _914, -(_904 * _904)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_749, _742), level(_1097 * (4.0 * (2.0 - _1097)))).xyz * (mix(_1104.xxx, _1104.yyy, _1088) * _1123)) + fast::min(fma((_1088 + ((float3(1.0) - _1088) * ((_1384 * _1384) * _1381))) * (((_1335 * _1335) * 0.3183098733425140380859375) * (0.5 / fma(_1195, sqrt(fma(_1040 * _1040, _1354, _1348)), _1040 * sqrt(fma(_1195 * _1195, _1354, _1348))))), _1123, _1005 * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1195), float3(65504.0));
    out.fragColor = float4(_1414, 1.0);
    return out;
}

