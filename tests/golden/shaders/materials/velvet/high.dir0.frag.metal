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
    half3 _383 = normalize(half3(in.v_normal));
    float3 _387 = fast::normalize(in.v_toEye);
    half _486 = _383.y;
    half _491 = _383.z;
    half _496 = _383.x;
    half3 _564 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _486)) + (half4(frame.sh[2]).xyz * _491)) + (half4(frame.sh[3]).xyz * _496)) + (((((half4(frame.sh[4]).xyz * (_496 * _486)) + (half4(frame.sh[5]).xyz * (_486 * _491))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _491, _491, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_496 * _491))) + (half4(frame.sh[8]).xyz * fma(_496, _496, half(-float(_486 * _486))))), half3(float3(0.0)));
    half4 _789 = half4(facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_383, half3(_387)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0)));
    half _621 = _789.z;
    float4 _637 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_387), _383)), level(params.facet_sheenLod));
    out.fragColor = float4(half4(fma(half4(_637).xyz, half3(float3(params.facet_sheenColor)) * _621, (half3(float3(params.facet_diffuseColor)) * _564) * fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _621, half(1.0))), half(1.0)));
    return out;
}

