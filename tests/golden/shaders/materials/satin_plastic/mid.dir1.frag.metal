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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _656 = normalize(half3(in.v_normal));
    half3 _760 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    half _824 = max(dot(_656, _760), half(9.9999997473787516355514526367188e-05));
    half3 _828 = reflect(-_760, _656);
    float4 _857 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_824, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _876 = facet_environment.sample(facet_environmentSmplr, float3(_828), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float4 _908 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_824, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1305 = half4(_908);
    half _921 = _1305.z;
    half _923 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _921, half(1.0));
    float4 _937 = facet_environment.sample(facet_environmentSmplr, float3(_828), level(params.facet_sheenLod));
    half3 _717 = half4(frame.lightDirection).xyz;
    half3 _729 = half4(frame.lightColor).xyz;
    half3 _1073 = normalize(_760 + _717);
    half _1015 = clamp(dot(_656, _717), half(0.0), half(1.0));
    half _1019 = clamp(dot(_656, _1073), half(0.0), half(1.0));
    half4 _1142 = half4(cross(_656, _1073), half(params.facet_alpha) * _1019) * half(64.0);
    half _1111 = _1015 + _824;
    half _1119 = half(6.283185482025146484375) * max(mix((half(2.0) * _1015) * _824, _1111, half(params.facet_alpha)), half(0.000244140625));
    half _1121 = (half(4096.0) * half(params.facet_alpha)) / (dot(_1142, _1142) * _1119);
    half _1175 = half(8192.0) * fma(half(-float(_1015)), _824, _1111);
    half _1179 = half(1.0) / (half(params.facet_sheenAlpha) * _1175);
    half3 _1208 = fma(half4(_937).xyz, half3(float3(params.facet_sheenColor)) * _921, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_876).xyz * mix(half4(_857).xxx, half4(_857).yyy, half3(float3(params.facet_f0)))) * _923) + min(fma(half3(float3(params.facet_f0)) * min(_1121 * (_1121 * _1119), half(65504.0)), (_729 * _1015) * _923, (half3(float3(params.facet_sheenColor)) * ((((fma(_1179, _1175, half(2.0)) * pow(max(fma(half(-float(_1019)), _1019, half(1.0)), half(0.0)), half(0.5) * (_1179 * _1175))) * half(0.15915493667125701904296875)) * (_1015 * (_1179 * (half(2048.0) * half(params.facet_sheenAlpha))))) * half4(_908).w)) * _729), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1208, half(1.0)));
    return out;
}

