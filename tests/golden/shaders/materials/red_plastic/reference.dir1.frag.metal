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
    float3 _654 = fast::normalize(in.v_normal);
    float3 _658 = fast::normalize(in.v_toEye);
    float _779 = _654.y;
    float _784 = _654.z;
    float _789 = _654.x;
    float _907 = fast::max(dot(_654, _658), 9.9999997473787516355514526367188e-05);
    float4 _946 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_907, params.facet_perceptualRoughness), level(0.0));
    float3 _965 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _946.y) - 1.0));
    float3 _1087 = fast::normalize(_658 + frame.lightDirection.xyz);
    float _1032 = fast::clamp(dot(_654, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1125 = cross(_654, _1087);
    float _1128 = fast::clamp(dot(_654, _1087), 0.0, 1.0) * params.facet_alpha;
    float _1137 = params.facet_alpha / fma(_1128, _1128, dot(_1125, _1125));
    float _1150 = params.facet_alpha * params.facet_alpha;
    float _1156 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1183 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1087), 0.0, 1.0);
    float _1186 = _1183 * _1183;
    float3 _1208 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _779)) + (frame.sh[2].xyz * _784)) + (frame.sh[3].xyz * _789)) + (((((frame.sh[4].xyz * (_789 * _779)) + (frame.sh[5].xyz * (_779 * _784))) + (frame.sh[6].xyz * fma(3.0 * _784, _784, -1.0))) + (frame.sh[7].xyz * (_789 * _784))) + (frame.sh[8].xyz * fma(_789, _789, -(_779 * _779)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_658, _654), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_946.xxx, _946.yyy, float3(params.facet_f0)) * _965)) + fast::min(fma((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1186 * _1186) * _1183))) * (((_1137 * _1137) * 0.3183098733425140380859375) * (0.5 / fma(_1032, sqrt(fma(_907 * _907, _1156, _1150)), _907 * sqrt(fma(_1032 * _1032, _1156, _1150))))), _965, float3(params.facet_diffuseColor) * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1032), float3(65504.0));
    out.fragColor = float4(_1208, 1.0);
    return out;
}

