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
    float3 _736 = fast::normalize(in.v_normal);
    float3 _743 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _849 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _898 = _736.y;
    float _903 = _736.z;
    float _908 = _736.x;
    float3 _999 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_849)), float3(0.0), float3(1.0)) * 1.0;
    float _1074 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _849), 0.0, 1.0);
    float3 _1082 = float3((0.1599999964237213134765625 * _1074) * _1074);
    float _1091 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _849), 0.08900000154972076416015625, 1.0);
    float _1034 = fast::max(dot(_736, _743), 9.9999997473787516355514526367188e-05);
    float4 _1098 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1034, _1091), level(0.0));
    float3 _1117 = float3(1.0) + (_1082 * ((1.0 / _1098.y) - 1.0));
    float _1263 = _1091 * _1091;
    float3 _1274 = fast::normalize(_743 + frame.lightDirection.xyz);
    float _1184 = fast::clamp(dot(_736, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1312 = cross(_736, _1274);
    float _1315 = fast::clamp(dot(_736, _1274), 0.0, 1.0) * _1263;
    float _1324 = _1263 / fma(_1315, _1315, dot(_1312, _1312));
    float _1337 = _1263 * _1263;
    float _1343 = fma(-_1263, _1263, 1.0);
    float _1370 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1274), 0.0, 1.0);
    float _1373 = _1370 * _1370;
    float3 _1403 = fma(_999, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _898)) + (frame.sh[2].xyz * _903)) + (frame.sh[3].xyz * _908)) + (((((frame.sh[4].xyz * (_908 * _898)) + (frame.sh[5].xyz * (_898 * _903))) + (frame.sh[6].xyz * fma(3.0 * _903, _903, -1.0))) + (frame.sh[7].xyz * (_908 * _903))) + (frame.sh[8].xyz * fma(_908, _908, -(_898 * _898)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_743, _736), level(_1091 * 4.0)).xyz * (mix(_1098.xxx, _1098.yyy, _1082) * _1117)) + fast::min(fma((_1082 + ((float3(1.0) - _1082) * ((_1373 * _1373) * _1370))) * (((_1324 * _1324) * 0.3183098733425140380859375) * (0.5 / fma(_1184, sqrt(fma(_1034 * _1034, _1343, _1337)), _1034 * sqrt(fma(_1184 * _1184, _1343, _1337))))), _1117, _999 * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1184), float3(65504.0));
    out.fragColor = float4(_1403, 1.0);
    return out;
}

