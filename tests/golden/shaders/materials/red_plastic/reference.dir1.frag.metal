#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
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
    float3 _658 = fast::normalize(in.v_normal);
    float3 _662 = fast::normalize(in.v_toEye);
    float _780 = _658.y;
    float _785 = _658.z;
    float _790 = _658.x;
    float _908 = fast::max(dot(_658, _662), 9.9999997473787516355514526367188e-05);
    float4 _947 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_908, params.facet_perceptualRoughness), level(0.0));
    float3 _966 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _947.y) - 1.0));
    float3 _1091 = fast::normalize(_662 + frame.lightDirection.xyz);
    float _1036 = fast::clamp(dot(_658, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1129 = cross(_658, _1091);
    float _1132 = fast::clamp(dot(_658, _1091), 0.0, 1.0) * params.facet_alpha;
    float _1141 = params.facet_alpha / fma(_1132, _1132, dot(_1129, _1129));
    float _1154 = params.facet_alpha * params.facet_alpha;
    float _1160 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1187 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1091), 0.0, 1.0);
    float _1190 = _1187 * _1187;
    float3 _1212 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _780)) + (frame.sh[2].xyz * _785)) + (frame.sh[3].xyz * _790)) + (((((frame.sh[4].xyz * (_790 * _780)) + (frame.sh[5].xyz * (_780 * _785))) + (frame.sh[6].xyz * fma(3.0 * _785, _785, -1.0))) + (frame.sh[7].xyz * (_790 * _785))) + (frame.sh[8].xyz * fma(_790, _790, -(_780 * _780)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_662, _658), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_947.xxx, _947.yyy, float3(params.facet_f0)) * _966)) + fast::min(fma((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1190 * _1190) * _1187))) * (((_1141 * _1141) * 0.3183098733425140380859375) * (0.5 / fma(_1036, sqrt(fma(_908 * _908, _1160, _1154)), _908 * sqrt(fma(_1036 * _1036, _1160, _1154))))), _966, float3(params.facet_diffuseColor) * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1036), float3(65504.0));
    out.fragColor = float4(_1212, 1.0);
    return out;
}

