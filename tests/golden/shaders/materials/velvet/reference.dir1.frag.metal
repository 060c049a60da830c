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
    float3 _521 = fast::normalize(in.v_normal);
    float3 _525 = fast::normalize(in.v_toEye);
    float _647 = _521.y;
    float _652 = _521.z;
    float _657 = _521.x;
    float _763 = fast::max(dot(_521, _525), 9.9999997473787516355514526367188e-05);
    float4 _768 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_763, params.facet_perceptualRoughness), level(0.0));
    float3 _804 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _845 = dot(_521, frame.lightDirection.xyz);
    float _847 = fast::clamp(_845, 0.0, 1.0);
    float _851 = fast::clamp(dot(_521, fast::normalize(_525 + frame.lightDirection.xyz)), 0.0, 1.0);
    float3 _959 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _647)) + (frame.sh[2].xyz * _652)) + (frame.sh[3].xyz * _657)) + (((((frame.sh[4].xyz * (_657 * _647)) + (frame.sh[5].xyz * (_647 * _652))) + (frame.sh[6].xyz * fma(3.0 * _652, _652, -1.0))) + (frame.sh[7].xyz * (_657 * _652))) + (frame.sh[8].xyz * fma(_657, _657, -(_647 * _647)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_525, _521), level(params.facet_perceptualRoughness * 4.0)).xyz * (_804 * _768.z)) + fast::min(fma(float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_845 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0)), fast::clamp(float3(params.subsurface) + float3(_847), float3(0.0), float3(1.0)), _804 * (((((2.0 + (1.0 / params.facet_alpha)) * pow(fast::max(fma(-_851, _851, 1.0), 0.0), 0.5 / params.facet_alpha)) * 0.15915493667125701904296875) * (_847 / (4.0 * fma(-_847, _763, _847 + _763)))) * _768.w)) * frame.lightColor.xyz, float3(65504.0));
    out.fragColor = float4(_959, 1.0);
    return out;
}

