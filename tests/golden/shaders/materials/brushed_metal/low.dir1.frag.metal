#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float anisotropy;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
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
    float4 v_tangent [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _554 = normalize(half3(in.v_normal));
    float3 _558 = fast::normalize(in.v_toEye);
    half3 _676 = half4(in.v_tangent).xyz;
    half _729 = max(dot(_554, half3(_558)), half(9.9999997473787516355514526367188e-05));
    half _839 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half3 _1105;
    if (float(_839) >= 0.0)
    {
        _1105 = _676;
    }
    else
    {
        _1105 = cross(_554, _676);
    }
    half _790 = dot(_1105, half3(_558));
    half _797 = min(abs(_839) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _802 = fma(half(-float(_797)), half(1.0) - _729, half(1.0));
    half _805 = _797 * _790;
    half _821 = (half(2.0) * fma(_802, _729, _805 * _790)) / fma(_802, _802, _805 * _805);
    float4 _846 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_729, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _872 = facet_environment.sample(facet_environmentSmplr, float3((((_554 * (_802 * _821)) + (_1105 * (_805 * _821))) - half3(_558))), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _750 = mix(half4(_846).xxx, half4(_846).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_846).y) - half(1.0))));
    half3 _610 = half4(frame.lightDirection).xyz;
    half _1001 = clamp(dot(reflect(-half3(_558), _554), _610), half(0.0), half(1.0));
    half _1004 = _1001 * _1001;
    half4 _1164 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1004 * _1004, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1016 = _1164.x;
    half3 _1025 = fma(half4(_872).xyz, _750, min((_750 * ((_1016 * _1016) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_554, _610), half(0.0), half(1.0))), half3(float3(65504.0))));
    out.fragColor = float4(half4(_1025, half(1.0)));
    return out;
}

