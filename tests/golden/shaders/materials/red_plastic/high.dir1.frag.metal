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
    half3 _484 = normalize(half3(in.v_normal));
    float3 _488 = fast::normalize(in.v_toEye);
    half _629 = max(dot(_484, half3(_488)), half(9.9999997473787516355514526367188e-05));
    float4 _662 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_629, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _681 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_488), _484)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _786 = fast::normalize(_488 + frame.lightDirection.xyz);
    half _739 = clamp(dot(_484, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half4 _851 = half4(cross(_484, half3(_786)), half(params.facet_alpha) * clamp(dot(_484, half3(_786)), half(0.0), half(1.0))) * half(64.0);
    half _832 = (half(4096.0) * half(params.facet_alpha)) / dot(_851, _851);
    half _876 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_786)), half(0.0), half(1.0));
    half _879 = _876 * _876;
    half3 _895 = fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_681).xyz * mix(half4(_662).xxx, half4(_662).yyy, half3(float3(params.facet_f0)))) + min(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_879 * _879) * _876))) * min(min((_832 * _832) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _739) * _629, _739 + _629, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * (half4(frame.lightColor).xyz * _739), half3(float3(65504.0)));
    out.fragColor = float4(half4(_895, half(1.0)));
    return out;
}

