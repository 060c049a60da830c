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
    char _m8_pad[12];
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
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
    half3 _314 = normalize(half3(in.v_normal));
    float3 _318 = fast::normalize(in.v_toEye);
    half4 _627 = half4(facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_314, half3(_318)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0)));
    half _488 = _627.z;
    float4 _504 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_318), _314)), level(params.facet_sheenLod));
    float4 _636 = float4(half4(fma(half4(_504).xyz, half3(float3(params.facet_sheenColor)) * _488, (half3(float3(params.facet_diffuseColor)) * max(((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _314.y)) + (half4(frame.sh[2]).xyz * _314.z)) + (half4(frame.sh[3]).xyz * _314.x), half3(float3(0.0)))) * fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _488, half(1.0))), half(1.0)));
    out.fragColor = _636;
    return out;
}

