#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float facet_perceptualRoughness;
    char _m3_pad[12];
    packed_float3 facet_f0;
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
    float3 _664 = fast::normalize(in.v_normal);
    float3 _668 = fast::normalize(in.v_toEye);
    float _919 = fast::max(dot(_664, _668), 9.9999997473787516355514526367188e-05);
    float4 _958 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_919, params.facet_perceptualRoughness), level(0.0));
    float3 _977 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _958.y) - 1.0));
    float3 _1104 = fast::normalize(_668 + frame.lightDirection.xyz);
    float _1049 = fast::clamp(dot(_664, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1142 = cross(_664, _1104);
    float _1145 = fast::clamp(dot(_664, _1104), 0.0, 1.0) * params.facet_alpha;
    float _1154 = params.facet_alpha / fma(_1145, _1145, dot(_1142, _1142));
    float _1167 = params.facet_alpha * params.facet_alpha;
    float _1173 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1200 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1104), 0.0, 1.0);
    float _1203 = _1200 * _1200;
    out.fragColor = float4(fma(facet_environment.sample(facet_environmentSmplr, reflect(-_668, _664), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, mix(_958.xxx, _958.yyy, float3(params.facet_f0)) * _977, fast::min((((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1203 * _1203) * _1200))) * (((_1154 * _1154) * 0.3183098733425140380859375) * (0.5 / fma(_1049, sqrt(fma(_919 * _919, _1173, _1167)), _919 * sqrt(fma(_1049 * _1049, _1173, _1167)))))) * _977) * (frame.lightColor.xyz * _1049), float3(65504.0))), 1.0);
    return out;
}

