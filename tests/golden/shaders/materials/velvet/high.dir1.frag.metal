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
    half3 _580 = normalize(half3(in.v_normal));
    float3 _584 = fast::normalize(in.v_toEye);
    half _704 = _580.y;
    half _709 = _580.z;
    half _714 = _580.x;
    half3 _782 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _704)) + (half4(frame.sh[2]).xyz * _709)) + (half4(frame.sh[3]).xyz * _714)) + (((((half4(frame.sh[4]).xyz * (_714 * _704)) + (half4(frame.sh[5]).xyz * (_704 * _709))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _709, _709, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_714 * _709))) + (half4(frame.sh[8]).xyz * fma(_714, _714, half(-float(_704 * _704))))), half3(float3(0.0)));
    half _822 = max(dot(_580, half3(_584)), half(9.9999997473787516355514526367188e-05));
    float4 _827 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_822, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _878 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1206 = half4(_827);
    half _840 = _1206.z;
    half _842 = fma(half(-float(max(_878.x, max(_878.y, _878.z)))), _840, half(1.0));
    float4 _885 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_584), _580)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _903 = dot(_580, half3(frame.lightDirection.xyz));
    half _905 = clamp(_903, half(0.0), half(1.0));
    half _973 = clamp(dot(_580, half3(fast::normalize(_584 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half _1017 = half(8192.0) * fma(half(-float(_905)), _822, _905 + _822);
    half _1021 = half(1.0) / (half(params.facet_alpha) * _1017);
    half3 _939 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_903 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_905), half3(float3(0.0)), half3(float3(1.0)))) * _842) + (_878 * ((((fma(_1021, _1017, half(2.0)) * pow(max(fma(half(-float(_973)), _973, half(1.0)), half(0.0)), half(0.5) * (_1021 * _1017))) * half(0.15915493667125701904296875)) * (_905 * (_1021 * (half(2048.0) * half(params.facet_alpha))))) * half4(_827).w))) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_885).xyz, _878 * _840, (half3(float3(params.facet_diffuseColor)) * _782) * _842) + _939, half(1.0)));
    return out;
}

