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
    float3 _578 = fast::normalize(in.v_normal);
    float3 _582 = fast::normalize(in.v_toEye);
    float _702 = _578.y;
    float _707 = _578.z;
    float _712 = _578.x;
    float _820 = fast::max(dot(_578, _582), 9.9999997473787516355514526367188e-05);
    float4 _825 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_820, params.facet_perceptualRoughness), level(0.0));
    float3 _876 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _838 = _825.z;
    float _840 = fma(-fast::max(_876.x, fast::max(_876.y, _876.z)), _838, 1.0);
    float _901 = dot(_578, frame.lightDirection.xyz);
    float _903 = fast::clamp(_901, 0.0, 1.0);
    float _971 = fast::clamp(dot(_578, fast::normalize(_582 + frame.lightDirection.xyz)), 0.0, 1.0);
    float _1013 = 8192.0 * fma(-_903, _820, _903 + _820);
    float _1017 = 1.0 / (params.facet_alpha * _1013);
    float3 _1059 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_582, _578), level(params.facet_perceptualRoughness * 4.0)).xyz, _876 * _838, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _702)) + (frame.sh[2].xyz * _707)) + (frame.sh[3].xyz * _712)) + (((((frame.sh[4].xyz * (_712 * _702)) + (frame.sh[5].xyz * (_702 * _707))) + (frame.sh[6].xyz * fma(3.0 * _707, _707, -1.0))) + (frame.sh[7].xyz * (_712 * _707))) + (frame.sh[8].xyz * fma(_712, _712, -(_702 * _702)))), float3(0.0))) * _840) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_901 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_903), float3(0.0), float3(1.0))) * _840) + (_876 * ((((fma(_1017, _1013, 2.0) * pow(fast::max(fma(-_971, _971, 1.0), 0.0), 0.5 * (_1017 * _1013))) * 0.15915493667125701904296875) * (_903 * (_1017 * (2048.0 * params.facet_alpha)))) * _825.w))) * frame.lightColor.xyz, float3(65504.0));
    out.fragColor = float4(_1059, 1.0);
    return out;
}

