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
    half3 _642 = normalize(half3(in.v_normal));
    float3 _646 = fast::normalize(in.v_toEye);
    half _803 = max(dot(_642, half3(_646)), half(9.9999997473787516355514526367188e-05));
    half3 _807 = reflect(-half3(_646), _642);
    float4 _843 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_803, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _874 = facet_environment.sample(facet_environmentSmplr, float3(_807), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _822 = mix(half4(_843).xxx, half4(_843).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_843).y) - half(1.0))));
    half _951 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _908 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_803, _951)), level(0.0));
    half3 _958 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1314 = half4(_908);
    half _921 = _1314.z;
    half _923 = fma(half(-float(max(_958.x, max(_958.y, _958.z)))), _921, half(1.0));
    half _967 = _951 * _951;
    float4 _984 = facet_environment.sample(facet_environmentSmplr, float3(_807), level(_951 * (half(4.0) * (half(2.0) - _951))));
    half3 _702 = half4(frame.lightDirection).xyz;
    half3 _714 = half4(frame.lightColor).xyz;
    half _1039 = clamp(dot(_642, _702), half(0.0), half(1.0));
    half _1043 = clamp(dot(_642, normalize(half3(_646) + _702)), half(0.0), half(1.0));
    half _1122 = clamp(dot(_807, _702), half(0.0), half(1.0));
    half _1125 = _1122 * _1122;
    half4 _1337 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1125 * _1125, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1137 = _1337.x;
    half _1171 = half(8192.0) * fma(half(-float(_1039)), _803, _1039 + _803);
    half _1175 = half(1.0) / (_967 * _1171);
    half3 _1204 = fma(half4(_984).xyz, _958 * _921, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_874).xyz * _822) * _923) + min(fma(_822 * ((_1137 * _1137) * half(5.092957973480224609375)), (_714 * _1039) * _923, (_958 * ((((fma(_1175, _1171, half(2.0)) * pow(max(fma(half(-float(_1043)), _1043, half(1.0)), half(0.0)), half(0.5) * (_1175 * _1171))) * half(0.15915493667125701904296875)) * (_1039 * (_1175 * (half(2048.0) * _967)))) * half4(_908).w)) * _714), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1204, half(1.0)));
    return out;
}

