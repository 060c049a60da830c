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
    float3 _569 = fast::normalize(in.v_normal);
    float3 _573 = fast::normalize(in.v_toEye);
    float _693 = _569.y;
    float _698 = _569.z;
    float _703 = _569.x;
    float _812 = fast::max(dot(_569, _573), 9.9999997473787516355514526367188e-05);
    float4 _817 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_812, params.facet_perceptualRoughness), level(0.0));
    float3 _871 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _830 = _817.z;
    float _832 = fma(-fast::max(_871.x, fast::max(_871.y, _871.z)), _830, 1.0);
    float _910 = dot(_569, frame.lightDirection.xyz);
    float _912 = fast::clamp(_910, 0.0, 1.0);
    float _924 = fast::clamp(dot(_569, fast::normalize(_573 + frame.lightDirection.xyz)), 0.0, 1.0);
    float _993 = 8192.0 * fma(-_912, _812, _912 + _812);
    float _997 = 1.0 / (params.facet_alpha * _993);
    float3 _1032 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_573, _569), level(params.facet_perceptualRoughness * 4.0)).xyz, _871 * _830, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _693)) + (frame.sh[2].xyz * _698)) + (frame.sh[3].xyz * _703)) + (((((frame.sh[4].xyz * (_703 * _693)) + (frame.sh[5].xyz * (_693 * _698))) + (frame.sh[6].xyz * fma(3.0 * _698, _698, -1.0))) + (frame.sh[7].xyz * (_703 * _698))) + (frame.sh[8].xyz * fma(_703, _703, -(_693 * _693)))), float3(0.0))) * _832) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_910 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_912), float3(0.0), float3(1.0))) * _832) + (_871 * ((((fma(_997, _993, 2.0) * pow(fast::max(fma(-_924, _924, 1.0), 0.0), 0.5 * (_997 * _993))) * 0.15915493667125701904296875) * (_912 * (_997 * (2048.0 * params.facet_alpha)))) * _817.w))) * frame.lightColor.xyz, float3(65504.0));
    out.fragColor = float4(_1032, 1.0);
    return out;
}

