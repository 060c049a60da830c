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
    float3 _758 = fast::normalize(in.v_normal);
    float3 _765 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _871 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _920 = _758.y;
    float _925 = _758.z;
    float _930 = _758.x;
    float3 _1021 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_871)), float3(0.0), float3(1.0)) * 1.0;
    float _1096 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _871), 0.0, 1.0);
    float3 _1104 = float3((0.1599999964237213134765625 * _1096) * _1096);
    float _1113 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _871), 0.08900000154972076416015625, 1.0);
    float _1056 = fast::max(dot(_758, _765), 9.9999997473787516355514526367188e-05);
    float4 _1120 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1056, _1113), level(0.0));
    float3 _1139 = float3(1.0) + (_1104 * ((1.0 / _1120.y) - 1.0));
    float _1285 = _1113 * _1113;
    float3 _1296 = fast::normalize(_765 + frame.lightDirection.xyz);
    float _1206 = fast::clamp(dot(_758, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1354 = cross(_758, _1296) * 64.0;
    float _1358 = fast::clamp(dot(_758, _1296), 0.0, 1.0) * (64.0 * _1285);
    float _1341 = (4096.0 * _1285) / fma(_1358, _1358, dot(_1354, _1354));
    float _1373 = _1285 * _1285;
    float _1379 = fma(-_1285, _1285, 1.0);
    float _1406 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1296), 0.0, 1.0);
    float _1409 = _1406 * _1406;
    float3 _1439 = fma(_1021, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _920)) + (frame.sh[2].xyz * _925)) + (frame.sh[3].xyz * _930)) + (((((frame.sh[4].xyz * (_930 * _920)) + (frame.sh[5].xyz * (_920 * _925))) + (frame.sh[6].xyz * fma(3.0 * _925, _925, -1.0))) + (frame.sh[7].xyz * (_930 * _925))) + (frame.sh[8].xyz * fma(_930, _930, -(_920 * _920)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_765, _758), level(_1113 * 4.0)).xyz * (mix(_1120.xxx, _1120.yyy, _1104) * _1139)) + fast::min(fma((_1104 + ((float3(1.0) - _1104) * ((_1409 * _1409) * _1406))) * (((_1341 * _1341) * 0.3183098733425140380859375) * (0.5 / fma(_1206, sqrt(fma(_1056 * _1056, _1379, _1373)), _1056 * sqrt(fma(_1206 * _1206, _1379, _1373))))), _1139, _1021 * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1206), float3(65504.0));
    out.fragColor = float4(_1439, 1.0);
    return out;
}

