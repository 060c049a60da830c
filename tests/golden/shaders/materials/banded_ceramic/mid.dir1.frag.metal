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
    half3 _551 = normalize(half3(in.v_normal));
    float3 _568 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _677 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _785 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _677)), half(0.0), half(1.0));
    half3 _793 = half3((half(0.1599999964237213134765625) * _785) * _785);
    half _802 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _677)), half(0.08900000154972076416015625), half(1.0));
    half _745 = max(dot(_551, half3(_568)), half(9.9999997473787516355514526367188e-05));
    float4 _809 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_745, _802)), level(0.0));
    half3 _828 = half3(float3(1.0)) + (_793 * ((half(1.0) / half4(_809).y) - half(1.0)));
    float4 _835 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_568), _551)), level(_802 * half(4.0)));
    half3 _605 = half4(frame.lightDirection).xyz;
    half _966 = _802 * _802;
    half3 _977 = normalize(half3(_568) + _605);
    half _893 = clamp(dot(_551, _605), half(0.0), half(1.0));
    half3 _1040 = cross(_551, _977) * half(64.0);
    half _1044 = clamp(dot(_551, _977), half(0.0), half(1.0)) * (half(64.0) * _966);
    half _1023 = half(6.283185482025146484375) * max(mix((half(2.0) * _893) * _745, _893 + _745, _966), half(0.000244140625));
    half _1025 = (half(4096.0) * _966) / (fma(_1044, _1044, dot(_1040, _1040)) * _1023);
    out.fragColor = float4(half4(fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_677))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_835).xyz * (mix(half4(_809).xxx, half4(_809).yyy, _793) * _828)) + min(((_793 * min(_1025 * (_1025 * _1023), half(65504.0))) * _828) * (half4(frame.lightColor).xyz * _893), half3(float3(65504.0))), half(1.0)));
    return out;
}

