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
    half3 _760 = normalize(half3(in.v_normal));
    float3 _767 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _873 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _922 = _760.y;
    half _927 = _760.z;
    half _932 = _760.x;
    half3 _1000 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _922)) + (half4(frame.sh[2]).xyz * _927)) + (half4(frame.sh[3]).xyz * _932)) + (((((half4(frame.sh[4]).xyz * (_932 * _922)) + (half4(frame.sh[5]).xyz * (_922 * _927))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _927, _927, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_932 * _927))) + (half4(frame.sh[8]).xyz * fma(_932, _932, half(-float(_922 * _922))))), half3(float3(0.0)));
    half3 _1023 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_873))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1098 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _873)), half(0.0), half(1.0));
    half3 _1106 = half3((half(0.1599999964237213134765625) * _1098) * _1098);
    half _1115 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _873)), half(0.08900000154972076416015625), half(1.0));
    half _1058 = max(dot(_760, half3(_767)), half(9.9999997473787516355514526367188e-05));
    float4 _1122 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1058, _1115)), level(0.0));
    half3 _1141 = half3(float3(1.0)) + (_1106 * ((half(1.0) / half4(_1122).y) - half(1.0)));
    float4 _1148 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_767), _760)), level(_1115 * half(4.0)));
    half _1287 = _1115 * _1115;
    float3 _1299 = fast::normalize(_767 + frame.lightDirection.xyz);
    half _1208 = clamp(dot(_760, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half4 _1364 = half4(cross(_760, half3(_1299)), _1287 * clamp(dot(_760, half3(_1299)), half(0.0), half(1.0))) * half(64.0);
    half _1345 = (half(4096.0) * _1287) / dot(_1364, _1364);
    half _1375 = _1287 * _1287;
    half _1381 = fma(half(-float(_1287)), _1287, half(1.0));
    half _1409 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1299)), half(0.0), half(1.0));
    half _1412 = _1409 * _1409;
    half3 _1442 = fma(_1023, _1000, half4(_1148).xyz * (mix(half4(_1122).xxx, half4(_1122).yyy, _1106) * _1141)) + min(fma((_1106 + ((half3(float3(1.0)) - _1106) * ((_1412 * _1412) * _1409))) * min(min((_1345 * _1345) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1208, sqrt(fma(_1058 * _1058, _1381, _1375)), _1058 * sqrt(fma(_1208 * _1208, _1381, _1375))), half(65504.0)), half(65504.0)), _1141, _1023 * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1208), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1442, half(1.0)));
    return out;
}

