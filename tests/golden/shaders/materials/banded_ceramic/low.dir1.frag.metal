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
    half3 _519 = normalize(half3(in.v_normal));
    float3 _536 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _648 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _757 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _648)), half(0.0), half(1.0));
    half3 _765 = half3((half(0.1599999964237213134765625) * _757) * _757);
    half _774 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _648)), half(0.08900000154972076416015625), half(1.0));
    half3 _720 = reflect(-half3(_536), _519);
    float4 _781 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_519, half3(_536)), half(9.9999997473787516355514526367188e-05)), _774)), level(0.0));
    float4 _810 = facet_environment.sample(facet_environmentSmplr, float3(_720), level(_774 * (half(4.0) * (half(2.0) - _774))));
    half3 _735 = mix(half4(_781).xxx, half4(_781).yyy, _765) * (half3(float3(1.0)) + (_765 * ((half(1.0) / half4(_781).y) - half(1.0))));
    half3 _573 = half4(frame.lightDirection).xyz;
    half _974 = clamp(dot(_720, _573), half(0.0), half(1.0));
    half _977 = _974 * _974;
    half4 _1124 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_977 * _977, _774), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _989 = _1124.x;
    out.fragColor = float4(half4(fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_648))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_810).xyz * _735) + min((_735 * ((_989 * _989) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_519, _573), half(0.0), half(1.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

