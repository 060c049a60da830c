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
    float3 _658 = fast::normalize(in.v_normal);
    float3 _662 = fast::normalize(in.v_toEye);
    float _913 = fast::max(dot(_658, _662), 9.9999997473787516355514526367188e-05);
    float4 _952 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_913, params.facet_perceptualRoughness), level(0.0));
    float3 _971 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _952.y) - 1.0));
    float3 _1093 = fast::normalize(_662 + frame.lightDirection.xyz);
    float _1038 = fast::clamp(dot(_658, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1131 = cross(_658, _1093);
    float _1134 = fast::clamp(dot(_658, _1093), 0.0, 1.0) * params.facet_alpha;
    float _1143 = params.facet_alpha / fma(_1134, _1134, dot(_1131, _1131));
    float _1156 = params.facet_alpha * params.facet_alpha;
    float _1162 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1189 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1093), 0.0, 1.0);
    float _1192 = _1189 * _1189;
    out.fragColor = float4(fma(facet_environment.sample(facet_environmentSmplr, reflect(-_662, _658), level(params.facet_perceptualRoughness * 4.0)).xyz, mix(_952.xxx, _952.yyy, float3(params.facet_f0)) * _971, fast::min((((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1192 * _1192) * _1189))) * (((_1143 * _1143) * 0.3183098733425140380859375) * (0.5 / fma(_1038, sqrt(fma(_913 * _913, _1162, _1156)), _913 * sqrt(fma(_1038 * _1038, _1162, _1156)))))) * _971) * (frame.lightColor.xyz * _1038), float3(65504.0))), 1.0);
    return out;
}

