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
    float3 _509 = fast::normalize(in.v_normal);
    float3 _513 = fast::normalize(in.v_toEye);
    float _622 = _509.y;
    float _627 = _509.z;
    float _632 = _509.x;
    float _750 = fast::max(dot(_509, _513), 9.9999997473787516355514526367188e-05);
    float3 _754 = reflect(-_513, _509);
    float4 _789 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_750, params.facet_perceptualRoughness), level(0.0));
    float _897 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _854 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_750, _897), level(0.0));
    float3 _904 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _867 = _854.z;
    float3 _890 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _622)) + (frame.sh[2].xyz * _627)) + (frame.sh[3].xyz * _632)) + (((((frame.sh[4].xyz * (_632 * _622)) + (frame.sh[5].xyz * (_622 * _627))) + (frame.sh[6].xyz * fma(3.0 * _627, _627, -1.0))) + (frame.sh[7].xyz * (_632 * _627))) + (frame.sh[8].xyz * fma(_632, _632, -(_622 * _622)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _754, level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_789.xxx, _789.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _789.y) - 1.0))))) * fma(-fast::max(_904.x, fast::max(_904.y, _904.z)), _867, 1.0);
    out.fragColor = float4(fma(facet_environment.sample(facet_environmentSmplr, _754, level(_897 * (4.0 * (2.0 - _897)))).xyz, _904 * _867, _890), 1.0);
    return out;
}

