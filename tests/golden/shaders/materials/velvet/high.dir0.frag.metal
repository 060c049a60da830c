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
    half3 _405 = normalize(half3(in.v_normal));
    float3 _409 = fast::normalize(in.v_toEye);
    half _508 = _405.y;
    half _513 = _405.z;
    half _518 = _405.x;
    half3 _586 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _508)) + (half4(frame.sh[2]).xyz * _513)) + (half4(frame.sh[3]).xyz * _518)) + (((((half4(frame.sh[4]).xyz * (_518 * _508)) + (half4(frame.sh[5]).xyz * (_508 * _513))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _513, _513, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_518 * _513))) + (half4(frame.sh[8]).xyz * fma(_518, _518, half(-float(_508 * _508))))), half3(float3(0.0)));
    half3 _686 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _828 = half4(facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_405, half3(_409)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0)));
    half _645 = _828.z;
    float4 _707 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_409), _405)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    out.fragColor = float4(half4(fma(half4(_707).xyz, _686 * _645, (half3(float3(params.facet_diffuseColor)) * _586) * fma(half(-float(max(_686.x, max(_686.y, _686.z)))), _645, half(1.0))), half(1.0)));
    return out;
}

