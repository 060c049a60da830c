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
    float3 _485 = fast::normalize(in.v_normal);
    float3 _489 = fast::normalize(in.v_toEye);
    float _598 = _485.y;
    float _603 = _485.z;
    float _608 = _485.x;
    float _726 = fast::max(dot(_485, _489), 9.9999997473787516355514526367188e-05);
    float3 _730 = reflect(-_489, _485);
    float4 _765 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_726, params.facet_perceptualRoughness), level(0.0));
    float _864 = fast::clamp(params.sheenRoughness, 0.08900000154972076416015625, 1.0);
    float4 _824 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_726, _864), level(0.0));
    float3 _871 = fast::clamp(float3(params.sheen), float3(0.0), float3(1.0));
    float _837 = _824.z;
    float3 _857 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _598)) + (frame.sh[2].xyz * _603)) + (frame.sh[3].xyz * _608)) + (((((frame.sh[4].xyz * (_608 * _598)) + (frame.sh[5].xyz * (_598 * _603))) + (frame.sh[6].xyz * fma(3.0 * _603, _603, -1.0))) + (frame.sh[7].xyz * (_608 * _603))) + (frame.sh[8].xyz * fma(_608, _608, -(_598 * _598)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _730, level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_765.xxx, _765.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _765.y) - 1.0))))) * fma(-fast::max(_871.x, fast::max(_871.y, _871.z)), _837, 1.0);
    out.fragColor = float4(fma(facet_environment.sample(facet_environmentSmplr, _730, level(_864 * 4.0)).xyz, _871 * _837, _857), 1.0);
    return out;
}

