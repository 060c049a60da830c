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
    float3 _677 = fast::normalize(in.v_normal);
    float3 _681 = fast::normalize(in.v_toEye);
    float _799 = _677.y;
    float _804 = _677.z;
    float _809 = _677.x;
    float _927 = fast::max(dot(_677, _681), 9.9999997473787516355514526367188e-05);
    float4 _966 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_927, params.facet_perceptualRoughness), level(0.0));
    float3 _985 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _966.y) - 1.0));
    float3 _1110 = fast::normalize(_681 + frame.lightDirection.xyz);
    float _1055 = fast::clamp(dot(_677, frame.lightDirection.xyz), 0.0, 1.0);
    float4 _1172 = float4(cross(_677, _1110), params.facet_alpha * fast::clamp(dot(_677, _1110), 0.0, 1.0)) * 64.0;
    float _1154 = (4096.0 * params.facet_alpha) / dot(_1172, _1172);
    float _1183 = params.facet_alpha * params.facet_alpha;
    float _1189 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1216 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1110), 0.0, 1.0);
    float _1219 = _1216 * _1216;
    float3 _1241 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _799)) + (frame.sh[2].xyz * _804)) + (frame.sh[3].xyz * _809)) + (((((frame.sh[4].xyz * (_809 * _799)) + (frame.sh[5].xyz * (_799 * _804))) + (frame.sh[6].xyz * fma(3.0 * _804, _804, -1.0))) + (frame.sh[7].xyz * (_809 * _804))) + (frame.sh[8].xyz * fma(_809, _809, -(_799 * _799)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_681, _677), level(params.facet_perceptualRoughness * (4.0 * (2.0 - params.facet_perceptualRoughness)))).xyz * (mix(_966.xxx, _966.yyy, float3(params.facet_f0)) * _985)) + fast::min(fma((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1219 * _1219) * _1216))) * (((_1154 * _1154) * 0.3183098733425140380859375) * (0.5 / fma(_1055, sqrt(fma(_927 * _927, _1189, _1183)), _927 * sqrt(fma(_1055 * _1055, _1189, _1183))))), _985, float3(params.facet_diffuseColor) * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1055), float3(65504.0));
    out.fragColor = float4(_1241, 1.0);
    return out;
}

