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
    half3 _764 = normalize(half3(in.v_normal));
    float3 _771 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _877 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _926 = _764.y;
    half _931 = _764.z;
    half _936 = _764.x;
    half3 _1004 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _926)) + (half4(frame.sh[2]).xyz * _931)) + (half4(frame.sh[3]).xyz * _936)) + (((((half4(frame.sh[4]).xyz * (_936 * _926)) + (half4(frame.sh[5]).xyz * (_926 * _931))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _931, _931, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_936 * _931))) + (half4(frame.sh[8]).xyz * fma(_936, _936, half(-float(_926 * _926))))), half3(float3(0.0)));
    half3 _1027 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_877))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1102 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _877)), half(0.0), half(1.0));
    half3 _1110 = half3((half(0.1599999964237213134765625) * _1102) * _1102);
    half _1119 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _877)), half(0.08900000154972076416015625), half(1.0));
    half _1062 = max(dot(_764, half3(_771)), half(9.9999997473787516355514526367188e-05));
    float4 _1126 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1062, _1119)), level(0.0));
    half3 _1145 = half3(float3(1.0)) + (_1110 * ((half(1.0) / half4(_1126).y) - half(1.0)));
    float4 _1155 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_771), _764)), level(_1119 * (half(4.0) * (half(2.0) - _1119))));
    half _1294 = _1119 * _1119;
    float3 _1306 = fast::normalize(_771 + frame.lightDirection.xyz);
    half _1215 = clamp(dot(_764, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half4 _1371 = half4(cross(_764, half3(_1306)), _1294 * clamp(dot(_764, half3(_1306)), half(0.0), half(1.0))) * half(64.0);
    half _1352 = (half(4096.0) * _1294) / dot(_1371, _1371);
    half _1382 = _1294 * _1294;
    half _1388 = fma(half(-float(_1294)), _1294, half(1.0));
    half _1416 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1306)), half(0.0), half(1.0));
    half _1419 = _1416 * _1416;
    half3 _1449 = fma(_1027, _1004, half4(_1155).xyz * (mix(half4(_1126).xxx, half4(_1126).yyy, _1110) * _1145)) + min(fma((_1110 + ((half3(float3(1.0)) - _1110) * ((_1419 * _1419) * _1416))) * min(min((_1352 * _1352) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1215, sqrt(fma(_1062 * _1062, _1388, _1382)), _1062 * sqrt(fma(_1215 * _1215, _1388, _1382))), half(65504.0)), half(65504.0)), _1145, _1027 * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1215), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1449, half(1.0)));
    return out;
}

