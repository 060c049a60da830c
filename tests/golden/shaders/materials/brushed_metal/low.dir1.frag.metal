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
    half _838 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half3 _1104;
    if (float(_838) >= 0.0)
    {
        _1104 = _676;
    }
    else
    {
        _1104 = cross(_554, _676);
    }
    half _790 = dot(_1104, half3(_558));
    half _797 = min(abs(_838) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _802 = fma(half(-float(_797)), half(1.0) - _729, half(1.0));
    half _805 = _797 * _790;
    float4 _845 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_729, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _871 = facet_environment.sample(facet_environmentSmplr, float3(((((_554 * _802) + (_1104 * _805)) * (half(512.0) * fma(_802, _729, _805 * _790))) - (half3(_558) * (half(256.0) * fma(_802, _802, _805 * _805))))), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _750 = mix(half4(_845).xxx, half4(_845).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_845).y) - half(1.0))));
    half3 _610 = half4(frame.lightDirection).xyz;
    half _1000 = clamp(dot(reflect(-half3(_558), _554), _610), half(0.0), half(1.0));
    half _1003 = _1000 * _1000;
    half4 _1164 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1003 * _1003, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1015 = _1164.x;
    half3 _1024 = fma(half4(_871).xyz, _750, min((_750 * ((_1015 * _1015) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_554, _610), half(0.0), half(1.0))), half3(float3(65504.0))));
    out.fragColor = float4(half4(_1024, half(1.0)));
    return out;
}

