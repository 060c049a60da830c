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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    float3 _665 = fast::normalize(in.v_normal);
    float3 _669 = fast::normalize(in.v_toEye);
    float _918 = fast::max(dot(_665, _669), 9.9999997473787516355514526367188e-05);
    float4 _960 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_918, params.facet_perceptualRoughness), level(0.0));
    float3 _979 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _960.y) - 1.0));
    float _1035 = fast::clamp(dot(_665, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1093 = fast::normalize(_669 + frame.lightDirection.xyz);
    float4 _1155 = float4(cross(_665, _1093), params.facet_alpha * fast::clamp(dot(_665, _1093), 0.0, 1.0)) * 64.0;
    float _1137 = (4096.0 * params.facet_alpha) / dot(_1155, _1155);
    float _1166 = params.facet_alpha * params.facet_alpha;
    float _1172 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1199 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1093), 0.0, 1.0);
    float _1202 = _1199 * _1199;
    out.fragColor = float4(fma(facet_environment.sample(facet_environmentSmplr, reflect(-_669, _665), level(params.facet_environmentLod)).xyz, mix(_960.xxx, _960.yyy, float3(params.facet_f0)) * _979, fast::min((((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1202 * _1202) * _1199))) * (((_1137 * _1137) * 0.3183098733425140380859375) * (0.5 / fma(_1035, sqrt(fma(_918 * _918, _1172, _1166)), _918 * sqrt(fma(_1035 * _1035, _1172, _1166)))))) * _979) * (frame.lightColor.xyz * _1035), float3(65504.0))), 1.0);
    return out;
}

