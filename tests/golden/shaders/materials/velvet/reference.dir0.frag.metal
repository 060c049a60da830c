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
    float3 _370 = fast::normalize(in.v_normal);
    float3 _374 = fast::normalize(in.v_toEye);
    float _473 = _370.y;
    float _478 = _370.z;
    float _483 = _370.x;
    float4 _596 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(fast::max(dot(_370, _374), 9.9999997473787516355514526367188e-05), params.facet_perceptualRoughness), level(0.0));
    float3 _642 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _609 = _596.z;
    float3 _631 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_374, _370), level(params.facet_perceptualRoughness * 4.0)).xyz, _642 * _609, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _473)) + (frame.sh[2].xyz * _478)) + (frame.sh[3].xyz * _483)) + (((((frame.sh[4].xyz * (_483 * _473)) + (frame.sh[5].xyz * (_473 * _478))) + (frame.sh[6].xyz * fma(3.0 * _478, _478, -1.0))) + (frame.sh[7].xyz * (_483 * _478))) + (frame.sh[8].xyz * fma(_483, _483, -(_473 * _473)))), float3(0.0))) * fma(-fast::max(_642.x, fast::max(_642.y, _642.z)), _609, 1.0));
    out.fragColor = float4(_631, 1.0);
    return out;
}

