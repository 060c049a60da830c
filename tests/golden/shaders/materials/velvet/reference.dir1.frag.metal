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
    float3 _572 = fast::normalize(in.v_normal);
    float3 _576 = fast::normalize(in.v_toEye);
    float _696 = _572.y;
    float _701 = _572.z;
    float _706 = _572.x;
    float _815 = fast::max(dot(_572, _576), 9.9999997473787516355514526367188e-05);
    float4 _820 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_815, params.facet_perceptualRoughness), level(0.0));
    float3 _874 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _833 = _820.z;
    float _835 = fma(-fast::max(_874.x, fast::max(_874.y, _874.z)), _833, 1.0);
    float _916 = dot(_572, frame.lightDirection.xyz);
    float _918 = fast::clamp(_916, 0.0, 1.0);
    float _930 = fast::clamp(dot(_572, fast::normalize(_576 + frame.lightDirection.xyz)), 0.0, 1.0);
    float _999 = 8192.0 * fma(-_918, _815, _918 + _815);
    float _1003 = 1.0 / (params.facet_alpha * _999);
    float3 _1038 = fma(facet_environment.sample(facet_environmentSmplr, reflect(-_576, _572), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz, _874 * _833, (float3(params.facet_diffuseColor) * fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _696)) + (frame.sh[2].xyz * _701)) + (frame.sh[3].xyz * _706)) + (((((frame.sh[4].xyz * (_706 * _696)) + (frame.sh[5].xyz * (_696 * _701))) + (frame.sh[6].xyz * fma(3.0 * _701, _701, -1.0))) + (frame.sh[7].xyz * (_706 * _701))) + (frame.sh[8].xyz * fma(_706, _706, -(_696 * _696)))), float3(0.0))) * _835) + fast::min(((((float3(params.facet_diffuseColor) * (0.3183098733425140380859375 * fast::clamp((_916 + 0.5) * 0.4444444477558135986328125, 0.0, 1.0))) * fast::clamp(float3(params.subsurface) + float3(_918), float3(0.0), float3(1.0))) * _835) + (_874 * ((((fma(_1003, _999, 2.0) * pow(fast::max(fma(-_930, _930, 1.0), 0.0), 0.5 * (_1003 * _999))) * 0.15915493667125701904296875) * (_918 * (_1003 * (2048.0 * params.facet_alpha)))) * _820.w))) * frame.lightColor.xyz, float3(65504.0));
    out.fragColor = float4(_1038, 1.0);
    return out;
}

