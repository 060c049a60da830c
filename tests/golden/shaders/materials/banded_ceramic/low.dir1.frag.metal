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
    half3 _496 = normalize(half3(in.v_normal));
    float3 _513 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _625 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _726 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _625)), half(0.0), half(1.0));
    half _743 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _625)), half(0.08900000154972076416015625), half(1.0));
    half3 _695 = reflect(-half3(_513), _496);
    float4 _750 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_496, half3(_513)), half(9.9999997473787516355514526367188e-05)), _743)), level(0.0));
    half3 _759 = mix(half4(_750).xxx, half4(_750).yyy, half3((half(0.1599999964237213134765625) * _726) * _726));
    float4 _769 = facet_environment.sample(facet_environmentSmplr, float3(_695), level(_743 * (half(4.0) * (half(2.0) - _743))));
    half3 _550 = half4(frame.lightDirection).xyz;
    half _933 = clamp(dot(_695, _550), half(0.0), half(1.0));
    half _936 = _933 * _933;
    half4 _1078 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_936 * _936, _743), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _948 = _1078.x;
    out.fragColor = float4(half4(fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_625))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_769).xyz * _759) + min((_759 * ((_948 * _948) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_496, _550), half(0.0), half(1.0))), half3(float3(65504.0))), half(1.0)));
    return out;
}

