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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    float3 _662 = fast::normalize(in.v_normal);
    float3 _666 = fast::normalize(in.v_toEye);
    float _784 = _662.y;
    float _789 = _662.z;
    float _794 = _662.x;
    float _910 = fast::max(dot(_662, _666), 9.9999997473787516355514526367188e-05);
    float4 _952 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(_910, params.facet_perceptualRoughness), level(0.0));
    float3 _971 = float3(1.0) + (float3(params.facet_f0) * ((1.0 / _952.y) - 1.0));
    float _1027 = fast::clamp(dot(_662, frame.lightDirection.xyz), 0.0, 1.0);
    float3 _1085 = fast::normalize(_666 + frame.lightDirection.xyz);
    float4 _1147 = float4(cross(_662, _1085), params.facet_alpha * fast::clamp(dot(_662, _1085), 0.0, 1.0)) * 64.0;
    float _1129 = (4096.0 * params.facet_alpha) / dot(_1147, _1147);
    float _1158 = params.facet_alpha * params.facet_alpha;
    float _1164 = fma(-params.facet_alpha, params.facet_alpha, 1.0);
    float _1191 = 1.0 - fast::clamp(dot(frame.lightDirection.xyz, _1085), 0.0, 1.0);
    float _1194 = _1191 * _1191;
    float3 _1216 = fma(float3(params.facet_diffuseColor), fast::max((((frame.sh[0].xyz + (frame.sh[1].xyz * _784)) + (frame.sh[2].xyz * _789)) + (frame.sh[3].xyz * _794)) + (((((frame.sh[4].xyz * (_794 * _784)) + (frame.sh[5].xyz * (_784 * _789))) + (frame.sh[6].xyz * fma(3.0 * _789, _789, -1.0))) + (frame.sh[7].xyz * (_794 * _789))) + (frame.sh[8].xyz * fma(_794, _794, -(_784 * _784)))), float3(0.0)), facet_environment.sample(facet_environmentSmplr, reflect(-_666, _662), level(params.facet_environmentLod)).xyz * (mix(_952.xxx, _952.yyy, float3(params.facet_f0)) * _971)) + fast::min(fma((float3(params.facet_f0) + ((float3(1.0) - float3(params.facet_f0)) * ((_1194 * _1194) * _1191))) * (((_1129 * _1129) * 0.3183098733425140380859375) * (0.5 / fma(_1027, sqrt(fma(_910 * _910, _1164, _1158)), _910 * sqrt(fma(_1027 * _1027, _1164, _1158))))), _971, float3(params.facet_diffuseColor) * 0.3183098733425140380859375) * (frame.lightColor.xyz * _1027), float3(65504.0));
    out.fragColor = float4(_1216, 1.0);
    return out;
}

