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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _536 = normalize(half3(in.v_normal));
    float3 _553 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _662 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _770 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _662)), half(0.0), half(1.0));
    half3 _778 = half3((half(0.1599999964237213134765625) * _770) * _770);
    half _787 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _662)), half(0.08900000154972076416015625), half(1.0));
    half _730 = max(dot(_536, half3(_553)), half(9.9999997473787516355514526367188e-05));
    float4 _794 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_730, _787)), level(0.0));
    half3 _813 = half3(float3(1.0)) + (_778 * ((half(1.0) / half4(_794).y) - half(1.0)));
    float4 _825 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_553), _536)), level(_787 * (half(4.0) * (half(2.0) - _787))));
    half3 _590 = half4(frame.lightDirection).xyz;
    half _956 = _787 * _787;
    half3 _967 = normalize(half3(_553) + _590);
    half _883 = clamp(dot(_536, _590), half(0.0), half(1.0));
    half3 _994 = cross(_536, _967);
    half _997 = clamp(dot(_536, _967), half(0.0), half(1.0)) * _956;
    half _1014 = max(mix((half(2.0) * _883) * _730, _883 + _730, _956), half(0.000244140625));
    half _1021 = (half(1024.0) * _956) / (fma(_997, _997, dot(_994, _994)) * (half(6433.98193359375) * _1014));
    out.fragColor = float4(half4(fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_662))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_825).xyz * (mix(half4(_794).xxx, half4(_794).yyy, _778) * _813)) + min(((_778 * min(_1021 * (_1021 * (half(6.283185482025146484375) * _1014)), half(65504.0))) * _813) * (half4(frame.lightColor).xyz * _883), half3(float3(65504.0))), half(1.0)));
    return out;
}

