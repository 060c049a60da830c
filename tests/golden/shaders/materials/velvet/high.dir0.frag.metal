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
    half3 _370 = normalize(half3(in.v_normal));
    float3 _374 = fast::normalize(in.v_toEye);
    half _473 = _370.y;
    half _478 = _370.z;
    half _483 = _370.x;
    half3 _551 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _473)) + (half4(frame.sh[2]).xyz * _478)) + (half4(frame.sh[3]).xyz * _483)) + (((((half4(frame.sh[4]).xyz * (_483 * _473)) + (half4(frame.sh[5]).xyz * (_473 * _478))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _478, _478, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_483 * _478))) + (half4(frame.sh[8]).xyz * fma(_483, _483, half(-float(_473 * _473))))), half3(float3(0.0)));
    half3 _642 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _770 = half4(facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_370, half3(_374)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0)));
    half _609 = _770.z;
    float4 _649 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_374), _370)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    out.fragColor = float4(half4(fma(half4(_649).xyz, _642 * _609, (half3(float3(params.facet_diffuseColor)) * _551) * fma(half(-float(max(_642.x, max(_642.y, _642.z)))), _609, half(1.0))), half(1.0)));
    return out;
}

