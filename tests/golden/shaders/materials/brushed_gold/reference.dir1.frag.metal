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
    float3 _681 = fast::normalize(in.v_normal);
    float3 _685 = fast::normalize(in.v_toEye);
    float _936 = fast::max(dot(_681, _685), 9.9999997473787516355514526367188e-05);
    float4 _975 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_936, params.facet_perceptualRoughness), level(0.0));
    float3 _994 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _975.y) - 1.0));
    float3 _1119 = fast::normalize(_685 + frame.lightDirection.xyz);
    float _1064 = fast::clamp(dot(_681, frame.lightDirection.xyz), 0.0, 1.0);
    float4 _1181 = float4(cross(_681, _1119), params.facet_alpha * fast::clamp(dot(_681, _1119), 0.0, 1.0)) * 64.0;
    float _1163 = (4096.0 * params.facet_alpha) / dot(_1181, _1181);
    float _1192 = params.facet_alpha * params.facet_alpha;
    float _1198 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1225 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1119), 0.0, 1.0);
    float _1228 = _1225 * _1225;
    out.fragColor = float4(fma(facet_environment.sample(facet_environmentSmplr, reflect(-_685, _681), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, mix(_975.xxx, _975.yyy, float3(params.facet_f0)) * _994, fast::min((((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1228 * _1228) * _1225))) * (((_1163 * _1163) * 0.3183098733425140380859375) * (0.5 / fma(_1064, sqrt(fma(_936 * _936, _1198, _1192)), _936 * sqrt(fma(_1064 * _1064, _1198, _1192)))))) * _994) * (frame.lightColor.xyz * _1064), float3(65504.0))), 1.0);
    return out;
}

