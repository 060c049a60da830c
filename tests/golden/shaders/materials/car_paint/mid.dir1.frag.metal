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
    half3 _549 = normalize(half3(in.v_normal));
    float3 _553 = fast::normalize(in.v_toEye);
    half _716 = max(dot(_549, half3(_553)), half(9.9999997473787516355514526367188e-05));
    half3 _720 = reflect(-half3(_553), _549);
    float4 _755 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_716, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _774 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_755).y) - half(1.0)));
    float4 _784 = facet_environment.sample(facet_environmentSmplr, float3(_720), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _601 = half4(frame.lightDirection).xyz;
    half3 _891 = normalize(half3(_553) + _601);
    half _842 = clamp(dot(_549, _601), half(0.0), half(1.0));
    half3 _918 = cross(_549, _891);
    half _921 = clamp(dot(_549, _891), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _938 = max(mix((half(2.0) * _842) * _716, _842 + _716, half(params.facet_alpha)), half(0.000244140625));
    half _945 = (half(1024.0) * half(params.facet_alpha)) / (fma(_921, _921, dot(_918, _918)) * (half(6433.98193359375) * _938));
    half _996 = half(1.0) - _716;
    half _999 = _996 * _996;
    half _1016 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1026 = facet_environment.sample(facet_environmentSmplr, float3(_720), level(_1016 * (half(4.0) * (half(2.0) - _1016))));
    half3 _990 = mix(fma(half4(_784).xyz, mix(half4(_755).xxx, half4(_755).yyy, half3(float3(params.facet_f0))) * _774, min(((half3(float3(params.facet_f0)) * min(_945 * (_945 * (half(6.283185482025146484375) * _938)), half(65504.0))) * _774) * (half4(frame.lightColor).xyz * _842), half3(float3(65504.0)))), half4(_1026).xyz, half3(fma(half(0.959999978542327880859375), (_999 * _999) * _996, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_990, half(1.0)));
    return out;
}

