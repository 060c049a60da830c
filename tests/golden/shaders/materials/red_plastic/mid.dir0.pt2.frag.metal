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
    float3 v_worldPosition [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _551 = normalize(half3(in.v_normal));
    float3 _567 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _749 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_551, half3(_567)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _728 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_567), _551)), level(params.facet_environmentLod));
    float3 _802 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _805 = dot(_802, _802);
    float3 _810 = _802 * rsqrt(fast::max(_805, 9.9999999392252902907785028219223e-09));
    float _814 = _805 * float(frame.punctualLights[0].positionFalloff.w);
    float _819 = fast::clamp(fma(-_814, _814, 1.0), 0.0, 1.0);
    float _838 = fast::clamp(fma(dot(-_810, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _902 = half3(_567) + half3(_810);
    half3 _912 = _902 * (half(64.0) * rsqrt(dot(_902, _902)));
    half _921 = clamp(dot(half3(_810), _912) * half(0.015625), half(0.0), half(1.0));
    half _1050 = max(_921 * _921, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1072 = half4(cross(_551, _912), half(params.facet_alpha) * clamp(dot(_551, _912), half(0.0), half(64.0)));
    half _1083 = half(params.facet_ggxAlphaScaled) / (dot(_1072, _1072) * _1050);
    float3 _1130 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1133 = dot(_1130, _1130);
    float3 _1138 = _1130 * rsqrt(fast::max(_1133, 9.9999999392252902907785028219223e-09));
    float _1142 = _1133 * float(frame.punctualLights[1].positionFalloff.w);
    float _1147 = fast::clamp(fma(-_1142, _1142, 1.0), 0.0, 1.0);
    float _1166 = fast::clamp(fma(dot(-_1138, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1230 = half3(_567) + half3(_1138);
    half3 _1240 = _1230 * (half(64.0) * rsqrt(dot(_1230, _1230)));
    half _1249 = clamp(dot(half3(_1138), _1240) * half(0.015625), half(0.0), half(1.0));
    half _1378 = max(_1249 * _1249, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1400 = half4(cross(_551, _1240), half(params.facet_alpha) * clamp(dot(_551, _1240), half(0.0), half(64.0)));
    half _1411 = half(params.facet_ggxAlphaScaled) / (dot(_1400, _1400) * _1378);
    half3 _1422 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_728).xyz * mix(half4(_749).xxx, half4(_749).yyy, half3(float3(params.facet_f0)))) + min((half3(float3(params.facet_f0)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_819) * half(_819)) / fast::max(_805, 9.9999997473787516355514526367188e-05)) * half(_838)) * half(_838)), float3(65504.0)))) * (min((_1083 * _1083) * _1050, half(65504.0)) * clamp(dot(_551, half3(_810)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((half3(float3(params.facet_f0)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1147) * half(_1147)) / fast::max(_1133, 9.9999997473787516355514526367188e-05)) * half(_1166)) * half(_1166)), float3(65504.0)))) * (min((_1411 * _1411) * _1378, half(65504.0)) * clamp(dot(_551, half3(_1138)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1422, half(1.0)));
    return out;
}

