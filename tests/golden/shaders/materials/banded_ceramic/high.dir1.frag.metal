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
    half3 _741 = normalize(half3(in.v_normal));
    float3 _748 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _857 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _906 = _741.y;
    half _911 = _741.z;
    half _916 = _741.x;
    half3 _984 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _906)) + (half4(frame.sh[2]).xyz * _911)) + (half4(frame.sh[3]).xyz * _916)) + (((((half4(frame.sh[4]).xyz * (_916 * _906)) + (half4(frame.sh[5]).xyz * (_906 * _911))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _911, _911, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_916 * _911))) + (half4(frame.sh[8]).xyz * fma(_916, _916, half(-float(_906 * _906))))), half3(float3(0.0)));
    half3 _1007 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_857))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1082 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _857)), half(0.0), half(1.0));
    half3 _1090 = half3((half(0.1599999964237213134765625) * _1082) * _1082);
    half _1099 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _857)), half(0.08900000154972076416015625), half(1.0));
    half _1042 = max(dot(_741, half3(_748)), half(9.9999997473787516355514526367188e-05));
    float4 _1106 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1042, _1099)), level(0.0));
    half3 _1125 = half3(float3(1.0)) + (_1090 * ((half(1.0) / half4(_1106).y) - half(1.0)));
    float4 _1132 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_748), _741)), level(_1099 * half(4.0)));
    half _1271 = _1099 * _1099;
    float3 _1283 = fast::normalize(_748 + frame.lightDirection.xyz);
    half _1192 = clamp(dot(_741, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1323 = cross(_741, half3(_1283));
    half _1326 = clamp(dot(_741, half3(_1283)), half(0.0), half(1.0)) * _1271;
    half _1335 = _1271 / fma(_1326, _1326, dot(_1323, _1323));
    half _1349 = _1271 * _1271;
    half _1355 = fma(half(-float(_1271)), _1271, half(1.0));
    half _1383 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1283)), half(0.0), half(1.0));
    half _1386 = _1383 * _1383;
    half3 _1416 = fma(_1007, _984, half4(_1132).xyz * (mix(half4(_1106).xxx, half4(_1106).yyy, _1090) * _1125)) + min(fma((_1090 + ((half3(float3(1.0)) - _1090) * ((_1386 * _1386) * _1383))) * min(min((_1335 * _1335) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1192, sqrt(fma(_1042 * _1042, _1355, _1349)), _1042 * sqrt(fma(_1192 * _1192, _1355, _1349))), half(65504.0)), half(65504.0)), _1125, _1007 * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1192), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1416, half(1.0)));
    return out;
}

