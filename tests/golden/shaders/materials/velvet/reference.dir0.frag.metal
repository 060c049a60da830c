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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    float3 _385 = fast::normalize(in.v_normal);
    float3 _389 = fast::normalize(in.v_toEye);
    float _488 = _385.y;
    float _493 = _385.z;
    float _498 = _385.x;
    float4 _610 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(fast::max(dot(_385, _389), 9.9999997473787516355514526367188e-05), params.facet_perceptualRoughness), level(0.0));
    float _623 = _610.z;
    float3 _651 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_389, _385), level(params.facet_sheenLod)).xyz, float3(params.facet_sheenColor) * _623, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _488)) + (frame.sh[2].xyz * _493)) + (frame.sh[3].xyz * _498)) + (((((frame.sh[4].xyz * (_498 * _488)) + (frame.sh[5].xyz * (_488 * _493))) + (frame.sh[6].xyz * fma(3.0 * _493, _493, -1.0))) + (frame.sh[7].xyz * (_498 * _493))) + (frame.sh[8].xyz * fma(_498, _498, -(_488 * _488)))), float3(0.0))) * fma(-fast::max(params.facet_sheenColor[0], fast::max(params.facet_sheenColor[1], params.facet_sheenColor[2])), _623, 1.0));
    out.fragColor = float4(_651, 1.0);
    return out;
}

