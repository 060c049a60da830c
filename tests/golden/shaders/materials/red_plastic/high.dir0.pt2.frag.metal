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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]])
{
    main0_out out = {};
    half3 _612 = normalize(half3(in.v_normal));
    float3 _628 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _739 = facet_irradiance.sample(facet_irradianceSmplr, float3(_612), level(0.0));
    half _786 = max(dot(_612, half3(_628)), half(9.9999997473787516355514526367188e-05));
    float4 _822 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_786, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _801 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_628), _612)), level(params.facet_environmentLod));
    float3 _875 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _878 = dot(_875, _875);
    float3 _883 = _875 * rsqrt(fast::max(_878, 9.9999999392252902907785028219223e-09));
    float _887 = _878 * float(frame.punctualLights[0].positionFalloff.w);
    float _892 = fast::clamp(fma(-_887, _887, 1.0), 0.0, 1.0);
    float _911 = fast::clamp(fma(dot(-_883, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _971 = clamp(dot(_612, half3(_883)), half(0.0), half(1.0));
    float3 _1027 = fast::normalize(_628 + _883);
    half _1067 = half(4096.0) * half(params.facet_alpha);
    half4 _1092 = half4(cross(_612, half3(_1027)), half(params.facet_alpha) * clamp(dot(_612, half3(_1027)), half(0.0), half(1.0))) * half(64.0);
    half _1073 = _1067 / dot(_1092, _1092);
    half _1117 = half(1.0) - clamp(dot(half3(_883), half3(_1027)), half(0.0), half(1.0));
    half _1120 = _1117 * _1117;
    half3 _1128 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1002 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1178 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1181 = dot(_1178, _1178);
    float3 _1186 = _1178 * rsqrt(fast::max(_1181, 9.9999999392252902907785028219223e-09));
    float _1190 = _1181 * float(frame.punctualLights[1].positionFalloff.w);
    float _1195 = fast::clamp(fma(-_1190, _1190, 1.0), 0.0, 1.0);
    float _1214 = fast::clamp(fma(dot(-_1186, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1274 = clamp(dot(_612, half3(_1186)), half(0.0), half(1.0));
    float3 _1330 = fast::normalize(_628 + _1186);
    half4 _1395 = half4(cross(_612, half3(_1330)), half(params.facet_alpha) * clamp(dot(_612, half3(_1330)), half(0.0), half(1.0))) * half(64.0);
    half _1376 = _1067 / dot(_1395, _1395);
    half _1420 = half(1.0) - clamp(dot(half3(_1186), half3(_1330)), half(0.0), half(1.0));
    half _1423 = _1420 * _1420;
    half3 _1445 = (fma(half3(float3(params.facet_diffuseColor)), half4(_739).xyz, half4(_801).xyz * mix(half4(_822).xxx, half4(_822).yyy, half3(float3(params.facet_f0)))) + min((_1002 + ((half3(float3(params.facet_f0)) + (_1128 * ((_1120 * _1120) * _1117))) * min(min((_1073 * _1073) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _971) * _786, _971 + _786, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_892) * half(_892)) / fast::max(_878, 9.9999997473787516355514526367188e-05)) * half(_911)) * half(_911)), float3(65504.0))) * _971), half3(float3(65504.0)))) + min((_1002 + ((half3(float3(params.facet_f0)) + (_1128 * ((_1423 * _1423) * _1420))) * min(min((_1376 * _1376) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1274) * _786, _1274 + _786, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1195) * half(_1195)) / fast::max(_1181, 9.9999997473787516355514526367188e-05)) * half(_1214)) * half(_1214)), float3(65504.0))) * _1274), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1445, half(1.0)));
    return out;
}

