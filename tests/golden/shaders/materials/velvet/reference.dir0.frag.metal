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
    float3 _405 = fast::normalize(in.v_normal);
    float3 _409 = fast::normalize(in.v_toEye);
    float _508 = _405.y;
    float _513 = _405.z;
    float _518 = _405.x;
    float4 _632 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(fast::max(dot(_405, _409), 9.9999997473787516355514526367188e-05), params.facet_perceptualRoughness), level(0.0));
    float3 _686 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _645 = _632.z;
    float3 _670 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_409, _405), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, _686 * _645, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _508)) + (frame.sh[2].xyz * _513)) + (frame.sh[3].xyz * _518)) + (((((frame.sh[4].xyz * (_518 * _508)) + (frame.sh[5].xyz * (_508 * _513))) + (frame.sh[6].xyz * fma(3.0 * _513, _513, -1.0))) + (frame.sh[7].xyz * (_518 * _513))) + (frame.sh[8].xyz * fma(_518, _518, -(_508 * _508)))), float3(0.0))) * fma(-fast::max(_686.x, fast::max(_686.y, _686.z)), _645, 1.0));
    out.fragColor = float4(_670, 1.0);
    return out;
}

