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
    half3 _669 = normalize(half3(in.v_normal));
    float3 _673 = fast::normalize(in.v_toEye);
    half _824 = max(dot(_669, half3(_673)), half(9.9999997473787516355514526367188e-05));
    half3 _828 = reflect(-half3(_673), _669);
    float4 _860 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_824, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _839 = facet_environment.sample(facet_environmentSmplr, float3(_828), level(params.facet_environmentLod));
    float4 _900 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_824, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1324 = half4(_900);
    half _913 = _1324.z;
    half _915 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _913, half(1.0));
    float4 _929 = facet_environment.sample(facet_environmentSmplr, float3(_828), level(params.facet_sheenLod));
    half3 _741 = half4(frame.lightColor).xyz;
    half _1004 = clamp(dot(_669, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    float3 _1066 = fast::normalize(_673 + frame.lightDirection.xyz);
    half _1011 = clamp(dot(_669, half3(_1066)), half(0.0), half(1.0));
    half4 _1131 = half4(cross(_669, half3(_1066)), half(params.facet_alpha) * _1011) * half(64.0);
    half _1112 = (half(4096.0) * half(params.facet_alpha)) / dot(_1131, _1131);
    half _1144 = _1004 + _824;
    half _1156 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1066)), half(0.0), half(1.0));
    half _1159 = _1156 * _1156;
    half _1200 = half(8192.0) * fma(half(-float(_1004)), _824, _1144);
    half _1204 = half(1.0) / (half(params.facet_sheenAlpha) * _1200);
    half3 _1047 = min(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1159 * _1159) * _1156))) * min(min((_1112 * _1112) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1004) * _824, _1144, half(params.facet_alpha)), half(65504.0)), half(65504.0)), (_741 * _1004) * _915, (half3(float3(params.facet_sheenColor)) * ((((fma(_1204, _1200, half(2.0)) * pow(max(fma(half(-float(_1011)), _1011, half(1.0)), half(0.0)), half(0.5) * (_1204 * _1200))) * half(0.15915493667125701904296875)) * (_1004 * (_1204 * (half(2048.0) * half(params.facet_sheenAlpha))))) * half4(_900).w)) * _741), half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_929).xyz, half3(float3(params.facet_sheenColor)) * _913, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_839).xyz * mix(half4(_860).xxx, half4(_860).yyy, half3(float3(params.facet_f0)))) * _915) + _1047, half(1.0)));
    return out;
}

