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
    float _854 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _903 = _741.y;
    half _908 = _741.z;
    half _913 = _741.x;
    half3 _981 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _903)) + (half4(frame.sh[2]).xyz * _908)) + (half4(frame.sh[3]).xyz * _913)) + (((((half4(frame.sh[4]).xyz * (_913 * _903)) + (half4(frame.sh[5]).xyz * (_903 * _908))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _908, _908, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_913 * _908))) + (half4(frame.sh[8]).xyz * fma(_913, _913, half(-float(_903 * _903))))), half3(float3(0.0)));
    half3 _1004 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_854))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1079 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _854)), half(0.0), half(1.0));
    half3 _1087 = half3((half(0.1599999964237213134765625) * _1079) * _1079);
    half _1096 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _854)), half(0.08900000154972076416015625), half(1.0));
    half _1039 = max(dot(_741, half3(_748)), half(9.9999997473787516355514526367188e-05));
    float4 _1103 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1039, _1096)), level(0.0));
    half3 _1122 = half3(float3(1.0)) + (_1087 * ((half(1.0) / half4(_1103).y) - half(1.0)));
    float4 _1129 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_748), _741)), level(_1096 * half(4.0)));
    half _1268 = _1096 * _1096;
    float3 _1280 = fast::normalize(_748 + frame.lightDirection.xyz);
    half _1189 = clamp(dot(_741, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1320 = cross(_741, half3(_1280));
    half _1323 = clamp(dot(_741, half3(_1280)), half(0.0), half(1.0)) * _1268;
    half _1332 = _1268 / fma(_1323, _1323, dot(_1320, _1320));
    half _1346 = _1268 * _1268;
    half _1352 = fma(half(-float(_1268)), _1268, half(1.0));
    half _1380 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1280)), half(0.0), half(1.0));
    half _1383 = _1380 * _1380;
    half3 _1413 = fma(_1004, _981, half4(_1129).xyz * (mix(half4(_1103).xxx, half4(_1103).yyy, _1087) * _1122)) + min(fma((_1087 + ((half3(float3(1.0)) - _1087) * ((_1383 * _1383) * _1380))) * min(min((_1332 * _1332) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1189, sqrt(fma(_1039 * _1039, _1352, _1346)), _1039 * sqrt(fma(_1189 * _1189, _1352, _1346))), half(65504.0)), half(65504.0)), _1122, _1004 * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1189), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1413, half(1.0)));
    return out;
}

