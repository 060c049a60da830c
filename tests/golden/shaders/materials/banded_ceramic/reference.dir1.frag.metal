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
    float3 _740 = fast::normalize(in.v_normal);
    float3 _747 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _853 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _902 = _740.y;
    float _907 = _740.z;
    float _912 = _740.x;
    float3 _1003 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_853)), float3(0.0), float3(1.0)) * 1.0;
    float _1078 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _853), 0.0, 1.0);
    float3 _1086 = float3((0.1599999964237213134765625 * _1078) * _1078);
    float _1095 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _853), 0.08900000154972076416015625, 1.0);
    float _1038 = fast::max(dot(_740, _747), 9.9999997473787516355514526367188e-05);
    float4 _1102 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1038, _1095), level(0.0));
    float3 _1121 = float3(1.0) + (_1086 * ((1.0 / _1102.y) - 1.0));
    float _1270 = _1095 * _1095;
    float3 _1281 = fast::normalize(_747 + frame.lightDirection.xyz);
    float _1191 = fast::clamp(dot(_740, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1319 = cross(_740, _1281);
    float _1322 = fast::clamp(dot(_740, _1281), 0.0, 1.0) * _1270;
    float _1331 = _1270 / fma(_1322, _1322, dot(_1319, _1319));
    float _1344 = _1270 * _1270;
    float _1350 = fma(-_1270, _1270, 1.0);
    float _1377 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1281), 0.0, 1.0);
    float _1380 = _1377 * _1377;
    float3 _1410 = fma(_1003, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _902)) + (frame.sh[2].xyz * _907)) + (frame.sh[3].xyz * _912)) + (((((frame.sh[4].xyz * (_912 * _902)) + (frame.sh[5].xyz * (_902 * _907))) + (frame.sh[6].xyz * fma(3.0 * _907, _907, -1.0))) + (frame.sh[7].xyz * (_912 * _907))) + (frame.sh[8].xyz * fma(_912, _912, -(_902 * _902)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_747, _740), level(_1095 * (4.0 * (2.0 - _1095)))).xyz * (mix(_1102.xxx, _1102.yyy, _1086) * _1121)) + fast::min(fma((_1086 + ((float3(1.0) - _1086) * ((_1380 * _1380) * _1377))) * (((_1331 * _1331) * 0.3183098733425140380859375) * (0.5 / fma(_1191, sqrt(fma(_1038 * _1038, _1350, _1344)), _1038 * sqrt(fma(_1191 * _1191, _1350, _1344))))), _1121, _1003 * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1191), float3(65504.0));
    out.fragColor = float4(_1410, 1.0);
    return out;
}

