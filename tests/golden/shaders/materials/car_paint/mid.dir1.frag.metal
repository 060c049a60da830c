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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _558 = normalize(half3(in.v_normal));
    float3 _562 = fast::normalize(in.v_toEye);
    half _726 = max(dot(_558, half3(_562)), half(9.9999997473787516355514526367188e-05));
    half3 _730 = reflect(-half3(_562), _558);
    float4 _765 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_726, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _784 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_765).y) - half(1.0)));
    float4 _794 = facet_environment.sample(facet_environmentSmplr, float3(_730), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _610 = half4(frame.lightDirection).xyz;
    half3 _901 = normalize(half3(_562) + _610);
    half _852 = clamp(dot(_558, _610), half(0.0), half(1.0));
    half4 _970 = half4(cross(_558, _901), half(params.facet_alpha) * clamp(dot(_558, _901), half(0.0), half(1.0))) * half(64.0);
    half _947 = half(6.283185482025146484375) * max(mix((half(2.0) * _852) * _726, _852 + _726, half(params.facet_alpha)), half(0.000244140625));
    half _949 = (half(4096.0) * half(params.facet_alpha)) / (dot(_970, _970) * _947);
    half _1016 = half(1.0) - _726;
    half _1019 = _1016 * _1016;
    float4 _1004 = facet_environment.sample(facet_environmentSmplr, float3(_730), level(params.facet_clearCoatLod));
    half3 _1010 = mix(fma(half4(_794).xyz, mix(half4(_765).xxx, half4(_765).yyy, half3(float3(params.facet_f0))) * _784, min(((half3(float3(params.facet_f0)) * min(_949 * (_949 * _947), half(65504.0))) * _784) * (half4(frame.lightColor).xyz * _852), half3(float3(65504.0)))), half4(_1004).xyz, half3(fma(half(0.959999978542327880859375), (_1019 * _1019) * _1016, half(0.039999999105930328369140625)) * half(params.facet_clearCoat)));
    out.fragColor = float4(half4(_1010, half(1.0)));
    return out;
}

