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
    half3 _534 = normalize(half3(in.v_normal));
    float3 _551 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _660 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _768 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _660)), half(0.0), half(1.0));
    half3 _776 = half3((half(0.1599999964237213134765625) * _768) * _768);
    half _785 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _660)), half(0.08900000154972076416015625), half(1.0));
    half _728 = max(dot(_534, half3(_551)), half(9.9999997473787516355514526367188e-05));
    float4 _792 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_728, _785)), level(0.0));
    half3 _811 = half3(float3(1.0)) + (_776 * ((half(1.0) / half4(_792).y) - half(1.0)));
    float4 _821 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_551), _534)), level(_785 * (half(4.0) * (half(2.0) - _785))));
    half3 _588 = half4(frame.lightDirection).xyz;
    half _952 = _785 * _785;
    half3 _963 = normalize(half3(_551) + _588);
    half _879 = clamp(dot(_534, _588), half(0.0), half(1.0));
    half3 _990 = cross(_534, _963);
    half _993 = clamp(dot(_534, _963), half(0.0), half(1.0)) * _952;
    half _1010 = max(mix((half(2.0) * _879) * _728, _879 + _728, _952), half(0.000244140625));
    half _1017 = (half(1024.0) * _952) / (fma(_993, _993, dot(_990, _990)) * (half(6433.98193359375) * _1010));
    out.fragColor = float4(half4(fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_660))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_821).xyz * (mix(half4(_792).xxx, half4(_792).yyy, _776) * _811)) + min(((_776 * min(_1017 * (_1017 * (half(6.283185482025146484375) * _1010)), half(65504.0))) * _811) * (half4(frame.lightColor).xyz * _879), half3(float3(65504.0))), half(1.0)));
    return out;
}

