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
    float facet_clearCoat;
    float facet_clearCoatAlpha;
    float facet_clearCoatLod;
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
    half3 _523 = normalize(half3(in.v_normal));
    float3 _527 = fast::normalize(in.v_toEye);
    half _694 = max(dot(_523, half3(_527)), half(9.9999997473787516355514526367188e-05));
    half3 _698 = reflect(-half3(_527), _523);
    float4 _734 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_694, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _763 = facet_environment.sample(facet_environmentSmplr, float3(_698), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _713 = mix(half4(_734).xxx, half4(_734).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_734).y) - half(1.0))));
    half3 _575 = half4(frame.lightDirection).xyz;
    half _892 = clamp(dot(_698, _575), half(0.0), half(1.0));
    half _895 = _892 * _892;
    half4 _1091 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_895 * _895, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _907 = _1091.x;
    half _954 = half(1.0) - _694;
    half _957 = _954 * _954;
    float4 _942 = facet_environment.sample(facet_environmentSmplr, float3(_698), level(params.facet_clearCoatLod));
    half3 _948 = mix(fma(half4(_763).xyz, _713, min((_713 * ((_907 * _907) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_523, _575), half(0.0), half(1.0))), half3(float3(65504.0)))), half4(_942).xyz, half3(fma(half(0.959999978542327880859375), (_957 * _957) * _954, half(0.039999999105930328369140625)) * half(params.facet_clearCoat)));
    out.fragColor = float4(half4(_948, half(1.0)));
    return out;
}

