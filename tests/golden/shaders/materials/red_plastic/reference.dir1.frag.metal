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
    float _776 = _654.y;
    float _781 = _654.z;
    float _786 = _654.x;
    float _904 = fast::max(dot(_654, _658), 9.9999997473787516355514526367188e-05);
    float4 _943 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_904, params.facet_perceptualRoughness), level(0.0));
    float3 _962 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _943.y) - 1.0));
    float3 _1084 = fast::normalize(_658 + frame.lightDirection.xyz);
    float _1029 = fast::clamp(dot(_654, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1122 = cross(_654, _1084);
    float _1125 = fast::clamp(dot(_654, _1084), 0.0, 1.0) * params.facet_alpha;
    float _1134 = params.facet_alpha / fma(_1125, _1125, dot(_1122, _1122));
    float _1147 = params.facet_alpha * params.facet_alpha;
    float _1153 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1180 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1084), 0.0, 1.0);
    float _1183 = _1180 * _1180;
    float3 _1205 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _776)) + (frame.sh[2].xyz * _781)) + (frame.sh[3].xyz * _786)) + (((((frame.sh[4].xyz * (_786 * _776)) + (frame.sh[5].xyz * (_776 * _781))) + (frame.sh[6].xyz * fma(3.0 * _781, _781, -1.0))) + (frame.sh[7].xyz * (_786 * _781))) + (frame.sh[8].xyz * fma(_786, _786, -(_776 * _776)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_658, _654), level(params.facet_perceptualRoughness * 4.0)).xyz * (mix(_943.xxx, _943.yyy, float3(params.facet_f0)) * _962)) + fast::min(fma((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1183 * _1183) * _1180))) * (((_1134 * _1134) * 0.3183098733425140380859375) * (0.5 / fma(_1029, sqrt(fma(_904 * _904, _1153, _1147)), _904 * sqrt(fma(_1029 * _1029, _1153, _1147))))), _962, float3(params.facet_diffuseColor) * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1029), float3(65504.0));
    out.fragColor = float4(_1205, 1.0);
    return out;
}

