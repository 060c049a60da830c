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
    float3 _662 = fast::normalize(in.v_normal);
    float3 _666 = fast::normalize(in.v_toEye);
    float _917 = fast::max(dot(_662, _666), 9.9999997473787516355514526367188e-05);
    float4 _956 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_917, params.facet_perceptualRoughness), level(0.0));
    float3 _975 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _956.y) - 1.0));
    float3 _1100 = fast::normalize(_666 + frame.lightDirection.xyz);
    float _1045 = fast::clamp(dot(_662, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1138 = cross(_662, _1100);
    float _1141 = fast::clamp(dot(_662, _1100), 0.0, 1.0) * params.facet_alpha;
    float _1150 = params.facet_alpha / fma(_1141, _1141, dot(_1138, _1138));
    float _1163 = params.facet_alpha * params.facet_alpha;
    float _1169 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1196 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1100), 0.0, 1.0);
    float _1199 = _1196 * _1196;
    out.fragColor = float4(fma(facet_environment.sample(facet_environmentSmplr, reflect(-_666, _662), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, mix(_956.xxx, _956.yyy, float3(params.facet_f0)) * _975, fast::min((((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1199 * _1199) * _1196))) * (((_1150 * _1150) * 0.3183098733425140380859375) * (0.5 / fma(_1045, sqrt(fma(_917 * _917, _1169, _1163)), _917 * sqrt(fma(_1045 * _1045, _1169, _1163)))))) * _975) * (frame.lightColor.xyz * _1045), float3(65504.0))), 1.0);
    return out;
}

