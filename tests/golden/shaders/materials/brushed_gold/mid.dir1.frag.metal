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
    half3 _474 = normalize(half3(in.v_normal));
    float3 _478 = fast::normalize(in.v_toEye);
    half _625 = max(dot(_474, half3(_478)), half(9.9999997473787516355514526367188e-05));
    float4 _664 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_625, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _683 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_664).y) - half(1.0)));
    float4 _690 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_478), _474)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _525 = half4(frame.lightDirection).xyz;
    half3 _797 = normalize(half3(_478) + _525);
    half _748 = clamp(dot(_474, _525), half(0.0), half(1.0));
    half3 _860 = cross(_474, _797) * half(64.0);
    half _864 = clamp(dot(_474, _797), half(0.0), half(1.0)) * (half(64.0) * half(params.facet_alpha));
    half _843 = half(6.283185482025146484375) * max(mix((half(2.0) * _748) * _625, _748 + _625, half(params.facet_alpha)), half(0.000244140625));
    half _845 = (half(4096.0) * half(params.facet_alpha)) / (fma(_864, _864, dot(_860, _860)) * _843);
    out.fragColor = float4(half4(fma(half4(_690).xyz, mix(half4(_664).xxx, half4(_664).yyy, half3(float3(params.facet_f0))) * _683, min(((half3(float3(params.facet_f0)) * min(_845 * (_845 * _843), half(65504.0))) * _683) * (half4(frame.lightColor).xyz * _748), half3(float3(65504.0)))), half(1.0)));
    return out;
}

