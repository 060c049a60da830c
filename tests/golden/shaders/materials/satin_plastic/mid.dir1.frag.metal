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
    half3 _631 = normalize(half3(in.v_normal));
    half3 _737 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    half _799 = max(dot(_631, _737), half(9.9999997473787516355514526367188e-05));
    half3 _803 = reflect(-_737, _631);
    float4 _835 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_799, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _814 = facet_environment.sample(facet_environmentSmplr, float3(_803), level(params.facet_environmentLod));
    float4 _875 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_799, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1259 = half4(_875);
    half _888 = _1259.z;
    half _890 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _888, half(1.0));
    float4 _904 = facet_environment.sample(facet_environmentSmplr, float3(_803), level(params.facet_sheenLod));
    half3 _692 = half4(frame.lightDirection).xyz;
    half3 _704 = half4(frame.lightColor).xyz;
    half _979 = clamp(dot(_631, _692), half(0.0), half(1.0));
    half3 _1040 = normalize(_737 + _692);
    half _986 = clamp(dot(_631, _1040), half(0.0), half(1.0));
    half _990 = clamp(dot(_692, _1040), half(0.0), half(1.0));
    half _1070 = max(_990 * _990, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1100 = half4(cross(_631, _1040), half(params.facet_alpha) * _986) * half(64.0);
    half _1080 = half(params.facet_ggxAlphaScaled) / (dot(_1100, _1100) * _1070);
    half _1133 = half(8192.0) * fma(half(-float(_979)), _799, _979 + _799);
    half _1137 = half(1.0) / (half(params.facet_sheenAlpha) * _1133);
    half3 _1166 = fma(half4(_904).xyz, half3(float3(params.facet_sheenColor)) * _888, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_814).xyz * mix(half4(_835).xxx, half4(_835).yyy, half3(float3(params.facet_f0)))) * _890) + min(fma(half3(float3(params.facet_f0)) * min((_1080 * _1080) * _1070, half(65504.0)), (_704 * _979) * _890, (half3(float3(params.facet_sheenColor)) * ((((fma(_1137, _1133, half(2.0)) * pow(max(fma(half(-float(_986)), _986, half(1.0)), half(0.0)), half(0.5) * (_1137 * _1133))) * half(0.15915493667125701904296875)) * (_979 * (_1137 * (half(2048.0) * half(params.facet_sheenAlpha))))) * half4(_875).w)) * _704), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1166, half(1.0)));
    return out;
}

