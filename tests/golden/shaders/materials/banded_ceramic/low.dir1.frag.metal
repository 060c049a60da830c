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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _515 = normalize(half3(in.v_normal));
    float3 _532 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _644 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _753 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _644)), half(0.0), half(1.0));
    half3 _761 = half3((half(0.1599999964237213134765625) * _753) * _753);
    half _770 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _644)), half(0.08900000154972076416015625), half(1.0));
    half3 _716 = reflect(-half3(_532), _515);
    float4 _777 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_515, half3(_532)), half(9.9999997473787516355514526367188e-05)), _770)), level(0.0));
    float4 _803 = facet_environment.sample(facet_environmentSmplr, float3(_716), level(_770 * half(4.0)));
    half3 _731 = mix(half4(_777).xxx, half4(_777).yyy, _761) * (half3(float3(1.0)) + (_761 * ((half(1.0) / half4(_777).y) - half(1.0))));
    half3 _569 = half4(frame.lightDirection).xyz;
    half _967 = clamp(dot(_716, _569), half(0.0), half(1.0));
    half _970 = _967 * _967;
    half4 _1116 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_970 * _970, _770), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _982 = _1116.x;
    out.fragColor = float4(half4(fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_644))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_803).xyz * _731) + min((_731 * ((_982 * _982) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_515, _569), half(0.0), half(1.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

