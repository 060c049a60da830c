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
    float _502 = _399.y;
    float _507 = _399.z;
    float _512 = _399.x;
    float4 _626 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(fast::max(dot(_399, _403), 9.9999997473787516355514526367188e-05), params.facet_perceptualRoughness), level(0.0));
    float3 _680 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _639 = _626.z;
    float3 _664 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_403, _399), level(params.facet_perceptualRoughness * 4.0)).xyz, _680 * _639, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _502)) + (frame.sh[2].xyz * _507)) + (frame.sh[3].xyz * _512)) + (((((frame.sh[4].xyz * (_512 * _502)) + (frame.sh[5].xyz * (_502 * _507))) + (frame.sh[6].xyz * fma(3.0 * _507, _507, -1.0))) + (frame.sh[7].xyz * (_512 * _507))) + (frame.sh[8].xyz * fma(_512, _512, -(_502 * _502)))), float3(0.0))) * fma(-fast::max(_680.x, fast::max(_680.y, _680.z)), _639, 1.0));
    out.fragColor = float4(_664, 1.0);
    return out;
}

