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
    half3 _459 = normalize(half3(in.v_normal));
    float3 _463 = fast::normalize(in.v_toEye);
    half _610 = max(dot(_459, half3(_463)), half(9.9999997473787516355514526367188e-05));
    float4 _649 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_610, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _668 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_649).y) - half(1.0)));
    float4 _680 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_463), _459)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _510 = half4(frame.lightDirection).xyz;
    half3 _787 = normalize(half3(_463) + _510);
    half _738 = clamp(dot(_459, _510), half(0.0), half(1.0));
    half3 _814 = cross(_459, _787);
    half _817 = clamp(dot(_459, _787), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _834 = max(mix((half(2.0) * _738) * _610, _738 + _610, half(params.facet_alpha)), half(0.000244140625));
    half _841 = (half(1024.0) * half(params.facet_alpha)) / (fma(_817, _817, dot(_814, _814)) * (half(6433.98193359375) * _834));
    out.fragColor = float4(half4(fma(half4(_680).xyz, mix(half4(_649).xxx, half4(_649).yyy, half3(float3(params.facet_f0))) * _668, min(((half3(float3(params.facet_f0)) * min(_841 * (_841 * (half(6.283185482025146484375) * _834)), half(65504.0))) * _668) * (half4(frame.lightColor).xyz * _738), half3(float3(65504.0)))), half(1.0)));
    return out;
}

