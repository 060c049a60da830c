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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]])
{
    main0_out out = {};
    half3 _338 = normalize(half3(in.v_normal));
    float3 _355 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _441 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float4 _467 = facet_irradiance.sample(facet_irradianceSmplr, float3(_338), level(0.0));
    half _558 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _441)), half(0.0), half(1.0));
    half _575 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _441)), half(0.08900000154972076416015625), half(1.0));
    float4 _582 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_338, half3(_355)), half(9.9999997473787516355514526367188e-05)), _575)), level(0.0));
    float4 _601 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_355), _338)), level(_575 * (half(4.0) * (half(2.0) - _575))));
    out.fragColor = float4(half4(fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_441))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half4(_467).xyz, half4(_601).xyz * mix(half4(_582).xxx, half4(_582).yyy, half3((half(0.1599999964237213134765625) * _558) * _558))), half(1.0)));
    return out;
}

