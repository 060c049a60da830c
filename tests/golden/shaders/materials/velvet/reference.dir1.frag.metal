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
    char _m8_pad[12];
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
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
    float3 _553 = fast::normalize(in.v_normal);
    float3 _557 = fast::normalize(in.v_toEye);
    float _677 = _553.y;
    float _682 = _553.z;
    float _687 = _553.x;
    float _794 = fast::max(dot(_553, _557), 9.9999997473787516355514526367188e-05);
    float4 _799 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_794, params.facet_perceptualRoughness), level(0.0));
    float _812 = _799.z;
    float _814 = fma(-fast::max(params.facet_sheenColor[0], fast::max(params.facet_sheenColor[1], params.facet_sheenColor[2])), _812, 1.0);
    float _884 = dot(_553, frame.lightDirection.xyz);
    float _886 = fast::clamp(_884, 0.0, 1.0);
    float _898 = fast::clamp(dot(_553, fast::normalize(_557 + frame.lightDirection.xyz)), 0.0, 1.0);
    float _967 = 8192.0 * fma(-_886, _794, _886 + _794);
    float _971 = 1.0 / (params.facet_alpha * _967);
    float3 _1006 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_557, _553), level(params.facet_sheenLod)).xyz, float3(params.facet_sheenColor) * _812, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _677)) + (frame.sh[2].xyz * _682)) + (frame.sh[3].xyz * _687)) + (((((frame.sh[4].xyz * (_687 * _677)) + (frame.sh[5].xyz * (_677 * _682))) + (frame.sh[6].xyz * fma(3.0 * _682, _682, -1.0))) + (frame.sh[7].xyz * (_687 * _682))) + (frame.sh[8].xyz * fma(_687, _687, -(_677 * _677)))), float3(0.0))) * _814) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_884 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_886), float3(0.0), float3(1.0))) * _814) + (float3(params.facet_sheenColor) * ((((fma(_971, _967, 2.0) * pow(fast::max(fma(-_898, _898, 1.0), 0.0), 0.5 * (_971 * _967))) * 0.15915493667125701904296875) * (_886 * (_971 * (2048.0 * params.facet_alpha)))) * _799.w))) * frame.lightColor.xyz, float3(65504.0));
    out.fragColor = float4(_1006, 1.0);
    return out;
}

