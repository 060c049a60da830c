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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    char _m11_pad[4];
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
    float facet_sheenRoughness;
    float facet_sheenAlpha;
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
    float _599 = _485.y;
    float _604 = _485.z;
    float _609 = _485.x;
    float _725 = fast::max(dot(_485, _489), 9.9999997473787516355514526367188e-05);
    float3 _729 = reflect(-_489, _485);
    float4 _767 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_725, params.facet_perceptualRoughness), level(0.0));
    float4 _817 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_725, params.facet_sheenRoughness), level(0.0));
    float _830 = _817.z;
    float3 _856 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _599)) + (frame.sh[2].xyz * _604)) + (frame.sh[3].xyz * _609)) + (((((frame.sh[4].xyz * (_609 * _599)) + (frame.sh[5].xyz * (_599 * _604))) + (frame.sh[6].xyz * fma(3.0 * _604, _604, -1.0))) + (frame.sh[7].xyz * (_609 * _604))) + (frame.sh[8].xyz * fma(_609, _609, -(_599 * _599)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, _729, level(params.facet_environmentLod)).xyz * (mix(_767.xxx, _767.yyy, float3(params.facet_f0)) * (float3(1.0) + (float3(params.facet_f0) * ((1.0 / _767.y) - 1.0))))) * fma(-fast::max(params.facet_sheenColor[0], fast::max(params.facet_sheenColor[1], params.facet_sheenColor[2])), _830, 1.0);
    out.fragColor = float4(fma(facet_environment.sample(facet_environmentSmplr, _729, level(params.facet_sheenLod)).xyz, float3(params.facet_sheenColor) * _830, _856), 1.0);
    return out;
}

