#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _471 = normalize(half3(in.v_normal));
    float3 _475 = fast::normalize(in.v_toEye);
    half _617 = max(dot(_471, half3(_475)), half(9.9999997473787516355514526367188e-05));
    float4 _656 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_617, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _675 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_656).y) - half(1.0)));
    float4 _682 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_475), _471)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _522 = half4(frame.lightDirection).xyz;
    half3 _789 = normalize(half3(_475) + _522);
    half _740 = clamp(dot(_471, _522), half(0.0), half(1.0));
    half3 _852 = cross(_471, _789) * half(64.0);
    half _856 = clamp(dot(_471, _789), half(0.0), half(1.0)) * (half(64.0) * half(params.facet_alpha));
    half _835 = half(6.283185482025146484375) * max(mix((half(2.0) * _740) * _617, _740 + _617, half(params.facet_alpha)), half(0.000244140625));
    half _837 = (half(4096.0) * half(params.facet_alpha)) / (fma(_856, _856, dot(_852, _852)) * _835);
    out.fragColor = float4(half4(fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_682).xyz * (mix(half4(_656).xxx, half4(_656).yyy, half3(float3(params.facet_f0))) * _675)) + min(((half3(float3(params.facet_f0)) * min(_837 * (_837 * _835), half(65504.0))) * _675) * (half4(frame.lightColor).xyz * _740), half3(float3(65504.0))), half(1.0)));
    return out;
}

