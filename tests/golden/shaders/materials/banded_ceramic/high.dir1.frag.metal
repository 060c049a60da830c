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
    half3 _747 = normalize(half3(in.v_normal));
    float3 _754 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _860 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _909 = _747.y;
    half _914 = _747.z;
    half _919 = _747.x;
    half3 _987 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _909)) + (half4(frame.sh[2]).xyz * _914)) + (half4(frame.sh[3]).xyz * _919)) + (((((half4(frame.sh[4]).xyz * (_919 * _909)) + (half4(frame.sh[5]).xyz * (_909 * _914))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _914, _914, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_919 * _914))) + (half4(frame.sh[8]).xyz * fma(_919, _919, half(-float(_909 * _909))))), half3(float3(0.0)));
    half3 _1010 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_860))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1085 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _860)), half(0.0), half(1.0));
    half3 _1093 = half3((half(0.1599999964237213134765625) * _1085) * _1085);
    half _1102 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _860)), half(0.08900000154972076416015625), half(1.0));
    half _1045 = max(dot(_747, half3(_754)), half(9.9999997473787516355514526367188e-05));
    float4 _1109 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1045, _1102)), level(0.0));
    half3 _1128 = half3(float3(1.0)) + (_1093 * ((half(1.0) / half4(_1109).y) - half(1.0)));
    float4 _1140 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_754), _747)), level(_1102 * (half(4.0) * (half(2.0) - _1102))));
    half _1279 = _1102 * _1102;
    float3 _1291 = fast::normalize(_754 + frame.lightDirection.xyz);
    half _1200 = clamp(dot(_747, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1331 = cross(_747, half3(_1291));
    half _1334 = clamp(dot(_747, half3(_1291)), half(0.0), half(1.0)) * _1279;
    half _1343 = _1279 / fma(_1334, _1334, dot(_1331, _1331));
    half _1357 = _1279 * _1279;
    half _1363 = fma(half(-float(_1279)), _1279, half(1.0));
    half _1391 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1291)), half(0.0), half(1.0));
    half _1394 = _1391 * _1391;
    half3 _1424 = fma(_1010, _987, half4(_1140).xyz * (mix(half4(_1109).xxx, half4(_1109).yyy, _1093) * _1128)) + min(fma((_1093 + ((half3(float3(1.0)) - _1093) * ((_1394 * _1394) * _1391))) * min(min((_1343 * _1343) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1200, sqrt(fma(_1045 * _1045, _1363, _1357)), _1045 * sqrt(fma(_1200 * _1200, _1363, _1357))), half(65504.0)), half(65504.0)), _1128, _1010 * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1200), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1424, half(1.0)));
    return out;
}

