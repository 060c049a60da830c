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
    half3 _669 = normalize(half3(in.v_normal));
    float3 _673 = fast::normalize(in.v_toEye);
    half _828 = max(dot(_669, half3(_673)), half(9.9999997473787516355514526367188e-05));
    half3 _832 = reflect(-half3(_673), _669);
    float4 _867 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_828, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _886 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_867).y) - half(1.0)));
    float4 _896 = facet_environment.sample(facet_environmentSmplr, float3(_832), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float4 _928 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_828, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1332 = half4(_928);
    half _941 = _1332.z;
    half _943 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _941, half(1.0));
    float4 _957 = facet_environment.sample(facet_environmentSmplr, float3(_832), level(params.facet_sheenLod));
    half3 _729 = half4(frame.lightDirection).xyz;
    half3 _741 = half4(frame.lightColor).xyz;
    half3 _1096 = normalize(half3(_673) + _729);
    half _1035 = clamp(dot(_669, _729), half(0.0), half(1.0));
    half _1039 = clamp(dot(_669, _1096), half(0.0), half(1.0));
    half4 _1165 = half4(cross(_669, _1096), half(params.facet_alpha) * _1039) * half(64.0);
    half _1134 = _1035 + _828;
    half _1142 = half(6.283185482025146484375) * max(mix((half(2.0) * _1035) * _828, _1134, half(params.facet_alpha)), half(0.000244140625));
    half _1144 = (half(4096.0) * half(params.facet_alpha)) / (dot(_1165, _1165) * _1142);
    half _1198 = half(8192.0) * fma(half(-float(_1035)), _828, _1134);
    half _1202 = half(1.0) / (half(params.facet_sheenAlpha) * _1198);
    half3 _1231 = fma(half4(_957).xyz, half3(float3(params.facet_sheenColor)) * _941, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_896).xyz * (mix(half4(_867).xxx, half4(_867).yyy, half3(float3(params.facet_f0))) * _886)) * _943) + min(fma((half3(float3(params.facet_f0)) * min(_1144 * (_1144 * _1142), half(65504.0))) * _886, (_741 * _1035) * _943, (half3(float3(params.facet_sheenColor)) * ((((fma(_1202, _1198, half(2.0)) * pow(max(fma(half(-float(_1039)), _1039, half(1.0)), half(0.0)), half(0.5) * (_1202 * _1198))) * half(0.15915493667125701904296875)) * (_1035 * (_1202 * (half(2048.0) * half(params.facet_sheenAlpha))))) * half4(_928).w)) * _741), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1231, half(1.0)));
    return out;
}

