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
    float3 _677 = fast::normalize(in.v_normal);
    float3 _681 = fast::normalize(in.v_toEye);
    float _932 = fast::max(dot(_677, _681), 9.9999997473787516355514526367188e-05);
    float4 _971 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_932, params.facet_perceptualRoughness), level(0.0));
    float3 _990 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _971.y) - 1.0));
    float3 _1112 = fast::normalize(_681 + frame.lightDirection.xyz);
    float _1057 = fast::clamp(dot(_677, frame.lightDirection.xyz), 0.0, 1.0);
    float4 _1174 = float4(cross(_677, _1112), params.facet_alpha * fast::clamp(dot(_677, _1112), 0.0, 1.0)) * 64.0;
    float _1156 = (4096.0 * params.facet_alpha) / dot(_1174, _1174);
    float _1185 = params.facet_alpha * params.facet_alpha;
    float _1191 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1218 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1112), 0.0, 1.0);
    float _1221 = _1218 * _1218;
    out.fragColor = float4(fma(facet_environment.sample(facet_environmentSmplr, reflect(-_681, _677), level(params.facet_perceptualRoughness * 4.0)).xyz, mix(_971.xxx, _971.yyy, float3(params.facet_f0)) * _990, fast::min((((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1221 * _1221) * _1218))) * (((_1156 * _1156) * 0.3183098733425140380859375) * (0.5 / fma(_1057, sqrt(fma(_932 * _932, _1191, _1185)), _932 * sqrt(fma(_1057 * _1057, _1191, _1185)))))) * _990) * (frame.lightColor.xyz * _1057), float3(65504.0))), 1.0);
    return out;
}

