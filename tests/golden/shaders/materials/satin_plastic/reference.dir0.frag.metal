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
    float3 _507 = fast::normalize(in.v_normal);
    float3 _511 = fast::normalize(in.v_toEye);
    float _620 = _507.y;
    float _625 = _507.z;
    float _630 = _507.x;
    float _748 = fast::max(dot(_507, _511), 9.9999997473787516355514526367188e-05);
    float3 _752 = reflect(-_511, _507);
    float4 _787 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_748, params.facet_perceptualRoughness), level(0.0));
    float _893 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _850 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_748, _893), level(0.0));
    float3 _900 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _863 = _850.z;
    float3 _886 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _620)) + (frame.sh[2].xyz * _625)) + (frame.sh[3].xyz * _630)) + (((((frame.sh[4].xyz * (_630 * _620)) + (frame.sh[5].xyz * (_620 * _625))) + (frame.sh[6].xyz * fma(3.0 * _625, _625, -1.0))) + (frame.sh[7].xyz * (_630 * _625))) + (frame.sh[8].xyz * fma(_630, _630, -(_620 * _620)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _752, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_787.xxx, _787.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _787.y) - 1.0))))) * fma(-fast::max(_900.x, fast::max(_900.y, _900.z)), _863, 1.0);
    out.fragColor = float4(fma(facet_environment.sample(facet_environmentSmplr, _752, level(_893 * (4.0 * (2.0 - _893)))).xyz, _900 * _863, _886), 1.0);
    return out;
}

