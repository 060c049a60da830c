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
    float3 _680 = fast::normalize(in.v_normal);
    float3 _684 = fast::normalize(in.v_toEye);
    float _935 = fast::max(dot(_680, _684), 9.9999997473787516355514526367188e-05);
    float4 _974 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_935, params.facet_perceptualRoughness), level(0.0));
    float3 _993 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _974.y) - 1.0));
    float3 _1115 = fast::normalize(_684 + frame.lightDirection.xyz);
    float _1060 = fast::clamp(dot(_680, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1173 = cross(_680, _1115) * 64.0;
    float _1177 = fast::clamp(dot(_680, _1115), 0.0, 1.0) * (64.0 * params.facet_alpha);
    float _1160 = (4096.0 * params.facet_alpha) / fma(_1177, _1177, dot(_1173, _1173));
    float _1192 = params.facet_alpha * params.facet_alpha;
    float _1198 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1225 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1115), 0.0, 1.0);
    float _1228 = _1225 * _1225;
    out.fragColor = float4(fma(facet_environment.sample(facet_environmentSmplr, reflect(-_684, _680), level(params.facet_perceptualRoughness * 4.0)).xyz, mix(_974.xxx, _974.yyy, float3(params.facet_f0)) * _993, fast::min((((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1228 * _1228) * _1225))) * (((_1160 * _1160) * 0.3183098733425140380859375) * (0.5 / fma(_1060, sqrt(fma(_935 * _935, _1198, _1192)), _935 * sqrt(fma(_1060 * _1060, _1198, _1192)))))) * _993) * (frame.lightColor.xyz * _1060), float3(65504.0))), 1.0);
    return out;
}

