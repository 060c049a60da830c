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
    float _852 = smoothstep(-params.bandSharpness, params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float _901 = _736.y;
    float _906 = _736.z;
    float _911 = _736.x;
    float3 _1002 = fast::clamp(mix(float3(params.clayColor), params.glazeColor, float3(_852)), float3(0.0), float3(1.0)) * 1.0;
    float _1077 = fast::clamp(mix(0.3499999940395355224609375, 0.60000002384185791015625, _852), 0.0, 1.0);
    float3 _1085 = float3((0.1599999964237213134765625 * _1077) * _1077);
    float _1094 = fast::clamp(mix(params.clayRoughness, params.glazeRoughness, _852), 0.08900000154972076416015625, 1.0);
    float _1037 = fast::max(dot(_736, _743), 9.9999997473787516355514526367188e-05);
    float4 _1101 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_1037, _1094), level(0.0));
    float3 _1120 = float3(1.0) + (_1085 * ((1.0 / _1101.y) - 1.0));
    float _1266 = _1094 * _1094;
    float3 _1277 = fast::normalize(_743 + frame.lightDirection.xyz);
    float _1187 = fast::clamp(dot(_736, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1315 = cross(_736, _1277);
    float _1318 = fast::clamp(dot(_736, _1277), 0.0, 1.0) * _1266;
    float _1327 = _1266 / fma(_1318, _1318, dot(_1315, _1315));
    float _1340 = _1266 * _1266;
    float _1346 = fma(-_1266, _1266, 1.0);
    float _1373 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1277), 0.0, 1.0);
    float _1376 = _1373 * _1373;
    float3 _1406 = fma(_1002, fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _901)) + (frame.sh[2].xyz * _906)) + (frame.sh[3].xyz * _911)) + (((((frame.sh[4].xyz * (_911 * _901)) + (frame.sh[5].xyz * (_901 * _906))) + (frame.sh[6].xyz * fma(3.0 * _906, _906, -1.0))) + (frame.sh[7].xyz * (_911 * _906))) + (frame.sh[8].xyz * fma(_911, _911, -(_901 * _901)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_743, _736), level(_1094 * 4.0)).xyz * (mix(_1101.xxx, _1101.yyy, _1085) * _1120)) + fast::min(fma((_1085 + ((float3(1.0) - _1085) * ((_1376 * _1376) * _1373))) * (((_1327 * _1327) * 0.3183098733425140380859375) * (0.5 / fma(_1187, sqrt(fma(_1037 * _1037, _1346, _1340)), _1037 * sqrt(fma(_1187 * _1187, _1346, _1340))))), _1120, _1002 * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1187), float3(65504.0));
    out.fragColor = float4(_1406, 1.0);
    return out;
}

