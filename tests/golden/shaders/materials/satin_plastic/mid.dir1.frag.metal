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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    char _m11_pad[4];
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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _646 = normalize(half3(in.v_normal));
    half3 _752 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    half _814 = max(dot(_646, _752), half(9.9999997473787516355514526367188e-05));
    half3 _818 = reflect(-_752, _646);
    float4 _850 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_814, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _829 = facet_environment.sample(facet_environmentSmplr, float3(_818), level(params.facet_environmentLod));
    float4 _890 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_814, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1283 = half4(_890);
    half _903 = _1283.z;
    half _905 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _903, half(1.0));
    float4 _919 = facet_environment.sample(facet_environmentSmplr, float3(_818), level(params.facet_sheenLod));
    half3 _707 = half4(frame.lightDirection).xyz;
    half3 _719 = half4(frame.lightColor).xyz;
    half _994 = clamp(dot(_646, _707), half(0.0), half(1.0));
    half3 _1055 = normalize(_752 + _707);
    half _1001 = clamp(dot(_646, _1055), half(0.0), half(1.0));
    half _1005 = clamp(dot(_707, _1055), half(0.0), half(1.0));
    half _1087 = max(_1005 * _1005, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1110 = half4(cross(_646, _1055), half(params.facet_alpha) * _1001) * half(64.0);
    half _1121 = half(params.facet_ggxAlphaScaled) / (dot(_1110, _1110) * _1087);
    half _1157 = half(8192.0) * fma(half(-float(_994)), _814, _994 + _814);
    half _1161 = half(1.0) / (half(params.facet_sheenAlpha) * _1157);
    half3 _1190 = fma(half4(_919).xyz, half3(float3(params.facet_sheenColor)) * _903, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_829).xyz * mix(half4(_850).xxx, half4(_850).yyy, half3(float3(params.facet_f0)))) * _905) + min(fma(half3(float3(params.facet_f0)) * min((_1121 * _1121) * _1087, half(65504.0)), (_719 * _994) * _905, (half3(float3(params.facet_sheenColor)) * ((((fma(_1161, _1157, half(2.0)) * pow(max(fma(half(-float(_1001)), _1001, half(1.0)), half(0.0)), half(0.5) * (_1161 * _1157))) * half(0.15915493667125701904296875)) * (_994 * (_1161 * (half(2048.0) * half(params.facet_sheenAlpha))))) * half4(_890).w)) * _719), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1190, half(1.0)));
    return out;
}

