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
    half3 _682 = normalize(half3(in.v_normal));
    float3 _686 = fast::normalize(in.v_toEye);
    half _839 = max(dot(_682, half3(_686)), half(9.9999997473787516355514526367188e-05));
    half3 _843 = reflect(-half3(_686), _682);
    float4 _872 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_839, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _891 = facet_environment.sample(facet_environmentSmplr, float3(_843), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float4 _923 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_839, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1351 = half4(_923);
    half _936 = _1351.z;
    half _938 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _936, half(1.0));
    float4 _952 = facet_environment.sample(facet_environmentSmplr, float3(_843), level(params.facet_sheenLod));
    half3 _754 = half4(frame.lightColor).xyz;
    float3 _1089 = fast::normalize(_686 + frame.lightDirection.xyz);
    half _1030 = clamp(dot(_682, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1034 = clamp(dot(_682, half3(_1089)), half(0.0), half(1.0));
    half4 _1154 = half4(cross(_682, half3(_1089)), half(params.facet_alpha) * _1034) * half(64.0);
    half _1135 = (half(4096.0) * half(params.facet_alpha)) / dot(_1154, _1154);
    half _1167 = _1030 + _839;
    half _1179 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1089)), half(0.0), half(1.0));
    half _1182 = _1179 * _1179;
    half _1223 = half(8192.0) * fma(half(-float(_1030)), _839, _1167);
    half _1227 = half(1.0) / (half(params.facet_sheenAlpha) * _1223);
    half3 _1070 = min(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1182 * _1182) * _1179))) * min(min((_1135 * _1135) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1030) * _839, _1167, half(params.facet_alpha)), half(65504.0)), half(65504.0)), (_754 * _1030) * _938, (half3(float3(params.facet_sheenColor)) * ((((fma(_1227, _1223, half(2.0)) * pow(max(fma(half(-float(_1034)), _1034, half(1.0)), half(0.0)), half(0.5) * (_1227 * _1223))) * half(0.15915493667125701904296875)) * (_1030 * (_1227 * (half(2048.0) * half(params.facet_sheenAlpha))))) * half4(_923).w)) * _754), half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_952).xyz, half3(float3(params.facet_sheenColor)) * _936, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_891).xyz * mix(half4(_872).xxx, half4(_872).yyy, half3(float3(params.facet_f0)))) * _938) + _1070, half(1.0)));
    return out;
}

