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
    float3 _574 = fast::normalize(in.v_normal);
    float3 _578 = fast::normalize(in.v_toEye);
    float _698 = _574.y;
    float _703 = _574.z;
    float _708 = _574.x;
    float _817 = fast::max(dot(_574, _578), 9.9999997473787516355514526367188e-05);
    float4 _822 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_817, params.facet_perceptualRoughness), level(0.0));
    float3 _876 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _835 = _822.z;
    float _837 = fma(-fast::max(_876.x, fast::max(_876.y, _876.z)), _835, 1.0);
    float _920 = dot(_574, frame.lightDirection.xyz);
    float _922 = fast::clamp(_920, 0.0, 1.0);
    float _934 = fast::clamp(dot(_574, fast::normalize(_578 + frame.lightDirection.xyz)), 0.0, 1.0);
    float _1003 = 8192.0 * fma(-_922, _817, _922 + _817);
    float _1007 = 1.0 / (params.facet_alpha * _1003);
    float3 _1042 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_578, _574), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, _876 * _835, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _698)) + (frame.sh[2].xyz * _703)) + (frame.sh[3].xyz * _708)) + (((((frame.sh[4].xyz * (_708 * _698)) + (frame.sh[5].xyz * (_698 * _703))) + (frame.sh[6].xyz * fma(3.0 * _703, _703, -1.0))) + (frame.sh[7].xyz * (_708 * _703))) + (frame.sh[8].xyz * fma(_708, _708, -(_698 * _698)))), float3(0.0))) * _837) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_920 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_922), float3(0.0), float3(1.0))) * _837) + (_876 * ((((fma(_1007, _1003, 2.0) * pow(fast::max(fma(-_934, _934, 1.0), 0.0), 0.5 * (_1007 * _1003))) * 0.15915493667125701904296875) * (_922 * (_1007 * (2048.0 * params.facet_alpha)))) * _822.w))) * frame.lightColor.xyz, float3(65504.0));
    out.fragColor = float4(_1042, 1.0);
    return out;
}

