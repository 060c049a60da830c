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
    float _695 = _569.y;
    float _700 = _569.z;
    float _705 = _569.x;
    float _814 = fast::max(dot(_569, _573), 9.9999997473787516355514526367188e-05);
    float4 _819 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_814, params.facet_perceptualRoughness), level(0.0));
    float3 _873 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _832 = _819.z;
    float _834 = fma(-fast::max(_873.x, fast::max(_873.y, _873.z)), _832, 1.0);
    float _912 = dot(_569, frame.lightDirection.xyz);
    float _914 = fast::clamp(_912, 0.0, 1.0);
    float _926 = fast::clamp(dot(_569, fast::normalize(_573 + frame.lightDirection.xyz)), 0.0, 1.0);
    float _995 = 8192.0 * fma(-_914, _814, _914 + _814);
    float _999 = 1.0 / (params.facet_alpha * _995);
    float3 _1034 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_573, _569), level(params.facet_perceptualRoughness * 4.0)).xyz, _873 * _832, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _695)) + (frame.sh[2].xyz * _700)) + (frame.sh[3].xyz * _705)) + (((((frame.sh[4].xyz * (_705 * _695)) + (frame.sh[5].xyz * (_695 * _700))) + (frame.sh[6].xyz * fma(3.0 * _700, _700, -1.0))) + (frame.sh[7].xyz * (_705 * _700))) + (frame.sh[8].xyz * fma(_705, _705, -(_695 * _695)))), float3(0.0))) * _834) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_912 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_914), float3(0.0), float3(1.0))) * _834) + (_873 * ((((fma(_999, _995, 2.0) * pow(fast::max(fma(-_926, _926, 1.0), 0.0), 0.5 * (_999 * _995))) * 0.15915493667125701904296875) * (_914 * (_999 * (2048.0 * params.facet_alpha)))) * _819.w))) * frame.lightColor.xyz, float3(65504.0));
    out.fragColor = float4(_1034, 1.0);
    return out;
}

