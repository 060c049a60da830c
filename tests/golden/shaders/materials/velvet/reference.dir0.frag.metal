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
    float3 _399 = fast::normalize(in.v_normal);
    float3 _403 = fast::normalize(in.v_toEye);
    float _504 = _399.y;
    float _509 = _399.z;
    float _514 = _399.x;
    float4 _628 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(fast::max(dot(_399, _403), 9.9999997473787516355514526367188e-05), params.facet_perceptualRoughness), level(0.0));
    float3 _682 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _641 = _628.z;
    float3 _666 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_403, _399), level(params.facet_perceptualRoughness * 4.0)).xyz, _682 * _641, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _504)) + (frame.sh[2].xyz * _509)) + (frame.sh[3].xyz * _514)) + (((((frame.sh[4].xyz * (_514 * _504)) + (frame.sh[5].xyz * (_504 * _509))) + (frame.sh[6].xyz * fma(3.0 * _509, _509, -1.0))) + (frame.sh[7].xyz * (_514 * _509))) + (frame.sh[8].xyz * fma(_514, _514, -(_504 * _504)))), float3(0.0))) * fma(-fast::max(_682.x, fast::max(_682.y, _682.z)), _641, 1.0));
    out.fragColor = float4(_666, 1.0);
    return out;
}

