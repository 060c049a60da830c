#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float facet_perceptualRoughness;
    char _m3_pad[12];
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
    half3 _473 = normalize(half3(in.v_normal));
    float3 _477 = fast::normalize(in.v_toEye);
    half _624 = max(dot(_473, half3(_477)), half(9.9999997473787516355514526367188e-05));
    float4 _663 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_624, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _682 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_663).y) - half(1.0)));
    float4 _689 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_477), _473)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _524 = half4(frame.lightDirection).xyz;
    half3 _796 = normalize(half3(_477) + _524);
    half _747 = clamp(dot(_473, _524), half(0.0), half(1.0));
    half4 _865 = half4(cross(_473, _796), half(params.facet_alpha) * clamp(dot(_473, _796), half(0.0), half(1.0))) * half(64.0);
    half _842 = half(6.283185482025146484375) * max(mix((half(2.0) * _747) * _624, _747 + _624, half(params.facet_alpha)), half(0.000244140625));
    half _844 = (half(4096.0) * half(params.facet_alpha)) / (dot(_865, _865) * _842);
    out.fragColor = float4(half4(fma(half4(_689).xyz, mix(half4(_663).xxx, half4(_663).yyy, half3(float3(params.facet_f0))) * _682, min(((half3(float3(params.facet_f0)) * min(_844 * (_844 * _842), half(65504.0))) * _682) * (half4(frame.lightColor).xyz * _747), half3(float3(65504.0)))), half(1.0)));
    return out;
}

