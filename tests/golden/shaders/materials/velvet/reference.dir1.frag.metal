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
    float3 _546 = fast::normalize(in.v_normal);
    float3 _550 = fast::normalize(in.v_toEye);
    float _670 = _546.y;
    float _675 = _546.z;
    float _680 = _546.x;
    float _788 = fast::max(dot(_546, _550), 9.9999997473787516355514526367188e-05);
    float4 _793 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_788, params.facet_perceptualRoughness), level(0.0));
    float3 _839 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _806 = _793.z;
    float _808 = fma(-fast::max(_839.x, fast::max(_839.y, _839.z)), _806, 1.0);
    float _873 = dot(_546, frame.lightDirection.xyz);
    float _875 = fast::clamp(_873, 0.0, 1.0);
    float _889 = fast::clamp(dot(_546, fast::normalize(_550 + frame.lightDirection.xyz)), 0.0, 1.0);
    float3 _1000 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_550, _546), level(params.facet_perceptualRoughness * 4.0)).xyz, _839 * _806, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _670)) + (frame.sh[2].xyz * _675)) + (frame.sh[3].xyz * _680)) + (((((frame.sh[4].xyz * (_680 * _670)) + (frame.sh[5].xyz * (_670 * _675))) + (frame.sh[6].xyz * fma(3.0 * _675, _675, -1.0))) + (frame.sh[7].xyz * (_680 * _675))) + (frame.sh[8].xyz * fma(_680, _680, -(_670 * _670)))), float3(0.0))) * _808) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_873 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_875), float3(0.0), float3(1.0))) * _808) + (_839 * (((((2.0 + (1.0 / params.facet_alpha)) * pow(fast::max(fma(-_889, _889, 1.0), 0.0), 0.5 / params.facet_alpha)) * 0.15915493667125701904296875) * (_875 / (4.0 * fma(-_875, _788, _875 + _788)))) * _793.w))) * frame.lightColor.xyz, float3(65504.0));
    out.fragColor = float4(_1000, 1.0);
    return out;
}

