#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    float facet_alpha;
    char _m8_pad[12];
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
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
    half3 _483 = normalize(half3(in.v_normal));
    float3 _487 = fast::normalize(in.v_toEye);
    half _656 = max(dot(_483, half3(_487)), half(9.9999997473787516355514526367188e-05));
    float4 _661 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_656, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _978 = half4(_661);
    half _674 = _978.z;
    half _676 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _674, half(1.0));
    float4 _690 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_487), _483)), level(params.facet_sheenLod));
    half3 _519 = half4(frame.lightDirection).xyz;
    half _746 = dot(_483, _519);
    half _748 = clamp(_746, half(0.0), half(1.0));
    half _760 = clamp(dot(_483, normalize(half3(_487) + _519)), half(0.0), half(1.0));
    half _829 = half(8192.0) * fma(half(-float(_748)), _656, _748 + _656);
    half _833 = half(1.0) / (half(params.facet_alpha) * _829);
    half3 _793 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_746 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_748), half3(float3(0.0)), half3(float3(1.0)))) * _676) + (half3(float3(params.facet_sheenColor)) * ((((fma(_833, _829, half(2.0)) * pow(max(fma(half(-float(_760)), _760, half(1.0)), half(0.0)), half(0.5) * (_833 * _829))) * half(0.15915493667125701904296875)) * (_748 * (_833 * (half(2048.0) * half(params.facet_alpha))))) * half4(_661).w))) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_690).xyz, half3(float3(params.facet_sheenColor)) * _674, (half3(float3(params.facet_diffuseColor)) * max(((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _483.y)) + (half4(frame.sh[2]).xyz * _483.z)) + (half4(frame.sh[3]).xyz * _483.x), half3(float3(0.0)))) * _676) + _793, half(1.0)));
    return out;
}

