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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    float3 _380 = fast::normalize(in.v_normal);
    float3 _384 = fast::normalize(in.v_toEye);
    float _481 = _380.y;
    float _486 = _380.z;
    float _491 = _380.x;
    float4 _649 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(fast::max(dot(_380, _384), 9.9999997473787516355514526367188e-05), params.facet_perceptualRoughness), level(0.0));
    float3 _676 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _481)) + (frame.sh[2].xyz * _486)) + (frame.sh[3].xyz * _491)) + (((((frame.sh[4].xyz * (_491 * _481)) + (frame.sh[5].xyz * (_481 * _486))) + (frame.sh[6].xyz * fma(3.0 * _486, _486, -1.0))) + (frame.sh[7].xyz * (_491 * _486))) + (frame.sh[8].xyz * fma(_491, _491, -(_481 * _481)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_384, _380), level(params.facet_environmentLod)).xyz * (mix(_649.xxx, _649.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _649.y) - 1.0)))));
    out.fragColor = float4(_676, 1.0);
    return out;
}

