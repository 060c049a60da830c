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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _609 = normalize(half3(in.v_normal));
    half3 _716 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    half _778 = max(dot(_609, _716), half(9.9999997473787516355514526367188e-05));
    half3 _782 = reflect(-_716, _609);
    float4 _815 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_778, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _824 = mix(half4(_815).xxx, half4(_815).yyy, half3(float3(params.facet_f0)));
    float4 _793 = facet_environment.sample(facet_environmentSmplr, float3(_782), level(params.facet_environmentLod));
    float4 _855 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_778, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1221 = half4(_855);
    half _868 = _1221.z;
    half _870 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _868, half(1.0));
    float4 _884 = facet_environment.sample(facet_environmentSmplr, float3(_782), level(params.facet_sheenLod));
    half3 _670 = half4(frame.lightDirection).xyz;
    half3 _682 = half4(frame.lightColor).xyz;
    half _959 = clamp(dot(_609, _670), half(0.0), half(1.0));
    half _966 = clamp(dot(_609, normalize(_716 + _670)), half(0.0), half(1.0));
    half _1045 = clamp(dot(_782, _670), half(0.0), half(1.0));
    half _1048 = _1045 * _1045;
    half4 _1242 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1048 * _1048, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1060 = _1242.x;
    half _1094 = half(8192.0) * fma(half(-float(_959)), _778, _959 + _778);
    half _1098 = half(1.0) / (half(params.facet_sheenAlpha) * _1094);
    half3 _1127 = fma(half4(_884).xyz, half3(float3(params.facet_sheenColor)) * _868, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_793).xyz * _824) * _870) + min(fma(_824 * ((_1060 * _1060) * half(5.092957973480224609375)), (_682 * _959) * _870, (half3(float3(params.facet_sheenColor)) * ((((fma(_1098, _1094, half(2.0)) * pow(max(fma(half(-float(_966)), _966, half(1.0)), half(0.0)), half(0.5) * (_1098 * _1094))) * half(0.15915493667125701904296875)) * (_959 * (_1098 * (half(2048.0) * half(params.facet_sheenAlpha))))) * half4(_855).w)) * _682), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1127, half(1.0)));
    return out;
}

