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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _572 = normalize(half3(in.v_normal));
    float3 _576 = fast::normalize(in.v_toEye);
    half3 _691 = half4(in.v_tangent).xyz;
    half _744 = max(dot(_572, half3(_576)), half(9.9999997473787516355514526367188e-05));
    half _852 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half3 _1138;
    if (float(_852) >= 0.0)
    {
        _1138 = _691;
    }
    else
    {
        _1138 = cross(_572, _691);
    }
    half _804 = dot(_1138, half3(_576));
    half _811 = min(abs(_852) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _816 = fma(half(-float(_811)), half(1.0) - _744, half(1.0));
    half _819 = _811 * _804;
    float4 _859 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_744, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _878 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_859).y) - half(1.0)));
    float4 _885 = facet_environment.sample(facet_environmentSmplr, float3(((((_572 * _816) + (_1138 * _819)) * (half(512.0) * fma(_816, _744, _819 * _804))) - (half3(_576) * (half(256.0) * fma(_816, _816, _819 * _819))))), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _628 = half4(frame.lightDirection).xyz;
    half3 _992 = normalize(half3(_576) + _628);
    half _943 = clamp(dot(_572, _628), half(0.0), half(1.0));
    half3 _1019 = cross(_572, _992);
    half _1022 = clamp(dot(_572, _992), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1039 = max(mix((half(2.0) * _943) * _744, _943 + _744, half(params.facet_alpha)), half(0.000244140625));
    half _1046 = (half(1024.0) * half(params.facet_alpha)) / (fma(_1022, _1022, dot(_1019, _1019)) * (half(6433.98193359375) * _1039));
    half3 _1058 = fma(half4(_885).xyz, mix(half4(_859).xxx, half4(_859).yyy, half3(float3(params.facet_f0))) * _878, min(((half3(float3(params.facet_f0)) * min(_1046 * (_1046 * (half(6.283185482025146484375) * _1039)), half(65504.0))) * _878) * (half4(frame.lightColor).xyz * _943), half3(float3(65504.0))));
    out.fragColor = float4(half4(_1058, half(1.0)));
    return out;
}

