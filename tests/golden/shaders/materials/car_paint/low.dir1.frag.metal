#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _529 = normalize(half3(in.v_normal));
    float3 _533 = fast::normalize(in.v_toEye);
    half _699 = max(dot(_529, half3(_533)), half(9.9999997473787516355514526367188e-05));
    half3 _703 = reflect(-half3(_533), _529);
    float4 _739 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_699, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _765 = facet_environment.sample(facet_environmentSmplr, float3(_703), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _718 = mix(half4(_739).xxx, half4(_739).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_739).y) - half(1.0))));
    half3 _581 = half4(frame.lightDirection).xyz;
    half _894 = clamp(dot(_703, _581), half(0.0), half(1.0));
    half _897 = _894 * _894;
    half4 _1110 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_897 * _897, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _909 = _1110.x;
    half _957 = half(1.0) - _699;
    half _960 = _957 * _957;
    float4 _984 = facet_environment.sample(facet_environmentSmplr, float3(_703), level(clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0)) * half(4.0)));
    half3 _951 = mix(fma(half4(_765).xyz, _718, min((_718 * ((_909 * _909) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_529, _581), half(0.0), half(1.0))), half3(float3(65504.0)))), half4(_984).xyz, half3(fma(half(0.959999978542327880859375), (_960 * _960) * _957, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_951, half(1.0)));
    return out;
}

