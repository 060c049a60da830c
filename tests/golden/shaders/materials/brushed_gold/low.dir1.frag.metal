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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    half3 _554 = normalize(half3(in.v_normal));
    half3 _636 = half3(in.v_toEye) * rsqrt(max(dot(half3(in.v_toEye), half3(in.v_toEye)), half(6.103515625e-05)));
    half _749 = max(dot(_554, _636), half(9.9999997473787516355514526367188e-05));
    float4 _791 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_749, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _810 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_791).y) - half(1.0)));
    float4 _767 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-_636, _554)), level(params.facet_environmentLod));
    half3 _593 = half4(frame.lightDirection).xyz;
    half _866 = clamp(dot(_554, _593), half(0.0), half(1.0));
    half3 _924 = normalize(_636 + _593);
    half4 _993 = half4(cross(_554, _924), half(params.facet_alpha) * clamp(dot(_554, _924), half(0.0), half(1.0))) * half(64.0);
    half _970 = half(6.283185482025146484375) * max(mix((half(2.0) * _866) * _749, _866 + _749, half(params.facet_alpha)), half(0.000244140625));
    half _972 = (half(4096.0) * half(params.facet_alpha)) / (dot(_993, _993) * _970);
    half3 _1015 = fma(half4(_767).xyz, mix(half4(_791).xxx, half4(_791).yyy, half3(float3(params.facet_f0))) * _810, min(((half3(float3(params.facet_f0)) * min(_972 * (_972 * _970), half(65504.0))) * _810) * (half4(frame.lightColor).xyz * _866), half3(float3(65504.0))));
    out.fragColor = float4(half4(_1015, half(1.0)));
    return out;
}

