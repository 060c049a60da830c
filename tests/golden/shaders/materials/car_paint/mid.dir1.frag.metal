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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _546 = normalize(half3(in.v_normal));
    float3 _550 = fast::normalize(in.v_toEye);
    half _713 = max(dot(_546, half3(_550)), half(9.9999997473787516355514526367188e-05));
    half3 _717 = reflect(-half3(_550), _546);
    float4 _752 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_713, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _771 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_752).y) - half(1.0)));
    float4 _778 = facet_environment.sample(facet_environmentSmplr, float3(_717), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _598 = half4(frame.lightDirection).xyz;
    half3 _885 = normalize(half3(_550) + _598);
    half _836 = clamp(dot(_546, _598), half(0.0), half(1.0));
    half3 _912 = cross(_546, _885);
    half _915 = clamp(dot(_546, _885), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _932 = max(mix((half(2.0) * _836) * _713, _836 + _713, half(params.facet_alpha)), half(0.000244140625));
    half _939 = (half(1024.0) * half(params.facet_alpha)) / (fma(_915, _915, dot(_912, _912)) * (half(6433.98193359375) * _932));
    half _990 = half(1.0) - _713;
    half _993 = _990 * _990;
    float4 _1017 = facet_environment.sample(facet_environmentSmplr, float3(_717), level(clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0)) * half(4.0)));
    half3 _984 = mix(fma(half4(_778).xyz, mix(half4(_752).xxx, half4(_752).yyy, half3(float3(params.facet_f0))) * _771, min(((half3(float3(params.facet_f0)) * min(_939 * (_939 * (half(6.283185482025146484375) * _932)), half(65504.0))) * _771) * (half4(frame.lightColor).xyz * _836), half3(float3(65504.0)))), half4(_1017).xyz, half3(fma(half(0.959999978542327880859375), (_993 * _993) * _990, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_984, half(1.0)));
    return out;
}

