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
    half3 _582 = normalize(half3(in.v_normal));
    float3 _599 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _708 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _808 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _708)), half(0.0), half(1.0));
    half3 _816 = half3((half(0.1599999964237213134765625) * _808) * _808);
    half _825 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _708)), half(0.08900000154972076416015625), half(1.0));
    float4 _832 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_582, half3(_599)), half(9.9999997473787516355514526367188e-05)), _825)), level(0.0));
    float4 _851 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_599), _582)), level(_825 * (half(4.0) * (half(2.0) - _825))));
    half3 _636 = half4(frame.lightDirection).xyz;
    half _1002 = _825 * _825;
    half3 _912 = half3(_599) + _636;
    half3 _922 = _912 * (half(64.0) * rsqrt(dot(_912, _912)));
    half _931 = clamp(dot(_636, _922) * half(0.015625), half(0.0), half(1.0));
    half4 _1150 = half4(cross(_582, _922), _1002 * clamp(dot(_582, _922), half(0.0), half(64.0)));
    half _1169 = (half(12.56637096405029296875) * max(_931 * _931, half(0.1500000059604644775390625))) * fma(half(-0.3125), _1002, half(1.00820004940032958984375));
    half _1174 = _1002 / ((dot(_1150, _1150) * half(0.000244140625)) * _1169);
    out.fragColor = float4(half4(fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_708))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_851).xyz * mix(half4(_832).xxx, half4(_832).yyy, _816)) + min((_816 * half4(frame.lightColor).xyz) * (min((_1174 * _1174) * _1169, half(65504.0)) * clamp(dot(_582, _636), half(0.0), half(1.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

