#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _663 = normalize(half3(in.v_normal));
    float3 _667 = fast::normalize(in.v_toEye);
    half _785 = _663.y;
    half _790 = _663.z;
    half _795 = _663.x;
    half3 _863 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _785)) + (half4(frame.sh[2]).xyz * _790)) + (half4(frame.sh[3]).xyz * _795)) + (((((half4(frame.sh[4]).xyz * (_795 * _785)) + (half4(frame.sh[5]).xyz * (_785 * _790))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _790, _790, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_795 * _790))) + (half4(frame.sh[8]).xyz * fma(_795, _795, half(-float(_785 * _785))))), half3(float3(0.0)));
    half _913 = max(dot(_663, half3(_667)), half(9.9999997473787516355514526367188e-05));
    float4 _952 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_913, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _971 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_952).y) - half(1.0)));
    float4 _981 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_667), _663)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1097 = fast::normalize(_667 + frame.lightDirection.xyz);
    half _1041 = clamp(dot(_663, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1137 = cross(_663, half3(_1097));
    half _1140 = clamp(dot(_663, half3(_1097)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1149 = half(params.facet_alpha) / fma(_1140, _1140, dot(_1137, _1137));
    half _1163 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1169 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1197 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1097)), half(0.0), half(1.0));
    half _1200 = _1197 * _1197;
    half3 _1222 = fma(half3(float3(params.facet_diffuseColor)), _863, half4(_981).xyz * (mix(half4(_952).xxx, half4(_952).yyy, half3(float3(params.facet_f0))) * _971)) + min(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1200 * _1200) * _1197))) * min(min((_1149 * _1149) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1041, sqrt(fma(_913 * _913, _1169, _1163)), _913 * sqrt(fma(_1041 * _1041, _1169, _1163))), half(65504.0)), half(65504.0)), _971, half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1041), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1222, half(1.0)));
    return out;
}

