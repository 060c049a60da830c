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
    float3 _555 = fast::normalize(in.v_normal);
    float3 _559 = fast::normalize(in.v_toEye);
    float _679 = _555.y;
    float _684 = _555.z;
    float _689 = _555.x;
    float _796 = fast::max(dot(_555, _559), 9.9999997473787516355514526367188e-05);
    float4 _801 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_796, params.facet_perceptualRoughness), level(0.0));
    float _814 = _801.z;
    float _816 = fma(-fast::max(params.facet_sheenColor[0], fast::max(params.facet_sheenColor[1], params.facet_sheenColor[2])), _814, 1.0);
    float _886 = dot(_555, frame.lightDirection.xyz);
    float _888 = fast::clamp(_886, 0.0, 1.0);
    float _900 = fast::clamp(dot(_555, fast::normalize(_559 + frame.lightDirection.xyz)), 0.0, 1.0);
    float _969 = 8192.0 * fma(-_888, _796, _888 + _796);
    float _973 = 1.0 / (params.facet_alpha * _969);
    float3 _1008 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_559, _555), level(params.facet_sheenLod)).xyz, float3(params.facet_sheenColor) * _814, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _679)) + (frame.sh[2].xyz * _684)) + (frame.sh[3].xyz * _689)) + (((((frame.sh[4].xyz * (_689 * _679)) + (frame.sh[5].xyz * (_679 * _684))) + (frame.sh[6].xyz * fma(3.0 * _684, _684, -1.0))) + (frame.sh[7].xyz * (_689 * _684))) + (frame.sh[8].xyz * fma(_689, _689, -(_679 * _679)))), float3(0.0))) * _816) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_886 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_888), float3(0.0), float3(1.0))) * _816) + (float3(params.facet_sheenColor) * ((((fma(_973, _969, 2.0) * pow(fast::max(fma(-_900, _900, 1.0), 0.0), 0.5 * (_973 * _969))) * 0.15915493667125701904296875) * (_888 * (_973 * (2048.0 * params.facet_alpha)))) * _801.w))) * frame.lightColor.xyz, float3(65504.0));
    out.fragColor = float4(_1008, 1.0);
    return out;
}

