#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    float3 _503 = fast::normalize(in.v_normal);
    float3 _507 = fast::normalize(in.v_toEye);
    float _616 = _503.y;
    float _621 = _503.z;
    float _626 = _503.x;
    float _744 = fast::max(dot(_503, _507), 9.9999997473787516355514526367188e-05);
    float3 _748 = reflect(-_507, _503);
    float4 _783 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_744, params.facet_perceptualRoughness), level(0.0));
    float _886 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _843 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_744, _886), level(0.0));
    float3 _893 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _856 = _843.z;
    float3 _879 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _616)) + (frame.sh[2].xyz * _621)) + (frame.sh[3].xyz * _626)) + (((((frame.sh[4].xyz * (_626 * _616)) + (frame.sh[5].xyz * (_616 * _621))) + (frame.sh[6].xyz * fma(3.0 * _621, _621, -1.0))) + (frame.sh[7].xyz * (_626 * _621))) + (frame.sh[8].xyz * fma(_626, _626, -(_616 * _616)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _748, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_783.xxx, _783.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _783.y) - 1.0))))) * fma(-fast::max(_893.x, fast::max(_893.y, _893.z)), _856, 1.0);
    out.fragColor = float4(fma(facet_environment.sample(facet_environmentSmplr, _748, level(_886 * 4.0)).xyz, _893 * _856, _879), 1.0);
    return out;
}

