#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    half3 _571 = normalize(half3(in.v_normal));
    float3 _575 = fast::normalize(in.v_toEye);
    half _695 = _571.y;
    half _700 = _571.z;
    half _705 = _571.x;
    half3 _773 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _695)) + (half4(frame.sh[2]).xyz * _700)) + (half4(frame.sh[3]).xyz * _705)) + (((((half4(frame.sh[4]).xyz * (_705 * _695)) + (half4(frame.sh[5]).xyz * (_695 * _700))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _700, _700, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_705 * _700))) + (half4(frame.sh[8]).xyz * fma(_705, _705, half(-float(_695 * _695))))), half3(float3(0.0)));
    half _814 = max(dot(_571, half3(_575)), half(9.9999997473787516355514526367188e-05));
    float4 _819 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_814, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _873 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1177 = half4(_819);
    half _832 = _1177.z;
    half _834 = fma(half(-float(max(_873.x, max(_873.y, _873.z)))), _832, half(1.0));
    float4 _889 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_575), _571)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _912 = dot(_571, half3(frame.lightDirection.xyz));
    half _914 = clamp(_912, half(0.0), half(1.0));
    half _926 = clamp(dot(_571, half3(fast::normalize(_575 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half _997 = half(8192.0) * fma(half(-float(_914)), _814, _914 + _814);
    half _1001 = half(1.0) / (half(params.facet_alpha) * _997);
    half3 _959 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_912 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_914), half3(float3(0.0)), half3(float3(1.0)))) * _834) + (_873 * ((((fma(_1001, _997, half(2.0)) * pow(max(fma(half(-float(_926)), _926, half(1.0)), half(0.0)), half(0.5) * (_1001 * _997))) * half(0.15915493667125701904296875)) * (_914 * (_1001 * (half(2048.0) * half(params.facet_alpha))))) * half4(_819).w))) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_889).xyz, _873 * _832, (half3(float3(params.facet_diffuseColor)) * _773) * _834) + _959, half(1.0)));
    return out;
}

