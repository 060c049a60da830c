#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    packed_float3 facet_f0;
    float facet_alpha;
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
    float facet_sheenRoughness;
    float facet_sheenAlpha;
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
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _633 = normalize(half3(in.v_normal));
    float3 _637 = fast::normalize(in.v_toEye);
    half _795 = max(dot(_633, half3(_637)), half(9.9999997473787516355514526367188e-05));
    half3 _799 = reflect(-half3(_637), _633);
    float4 _835 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_795, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _864 = facet_environment.sample(facet_environmentSmplr, float3(_799), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _814 = mix(half4(_835).xxx, half4(_835).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_835).y) - half(1.0))));
    float4 _896 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_795, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1270 = half4(_896);
    half _909 = _1270.z;
    half _911 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _909, half(1.0));
    float4 _925 = facet_environment.sample(facet_environmentSmplr, float3(_799), level(params.facet_sheenLod));
    half3 _693 = half4(frame.lightDirection).xyz;
    half3 _705 = half4(frame.lightColor).xyz;
    half _1003 = clamp(dot(_633, _693), half(0.0), half(1.0));
    half _1007 = clamp(dot(_633, normalize(half3(_637) + _693)), half(0.0), half(1.0));
    half _1086 = clamp(dot(_799, _693), half(0.0), half(1.0));
    half _1089 = _1086 * _1086;
    half4 _1292 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1089 * _1089, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1101 = _1292.x;
    half _1135 = half(8192.0) * fma(half(-float(_1003)), _795, _1003 + _795);
    half _1139 = half(1.0) / (half(params.facet_sheenAlpha) * _1135);
    half3 _1168 = fma(half4(_925).xyz, half3(float3(params.facet_sheenColor)) * _909, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_864).xyz * _814) * _911) + min(fma(_814 * ((_1101 * _1101) * half(5.092957973480224609375)), (_705 * _1003) * _911, (half3(float3(params.facet_sheenColor)) * ((((fma(_1139, _1135, half(2.0)) * pow(max(fma(half(-float(_1007)), _1007, half(1.0)), half(0.0)), half(0.5) * (_1139 * _1135))) * half(0.15915493667125701904296875)) * (_1003 * (_1139 * (half(2048.0) * half(params.facet_sheenAlpha))))) * half4(_896).w)) * _705), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1168, half(1.0)));
    return out;
}

