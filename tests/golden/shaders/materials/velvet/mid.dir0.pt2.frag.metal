#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    float3 v_worldPosition [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _511 = normalize(half3(in.v_normal));
    float3 _527 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _669 = max(dot(_511, half3(_527)), half(9.9999997473787516355514526367188e-05));
    float4 _674 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_669, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _725 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1322 = half4(_674);
    half _687 = _1322.z;
    half4 _1326 = half4(_674);
    half _691 = _1326.w;
    float4 _732 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_527), _511)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _769 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _772 = dot(_769, _769);
    float3 _777 = _769 * rsqrt(fast::max(_772, 9.9999999392252902907785028219223e-09));
    float _781 = _772 * float(frame.punctualLights[0].positionFalloff.w);
    float _786 = fast::clamp(fma(-_781, _781, 1.0), 0.0, 1.0);
    float _805 = fast::clamp(fma(dot(-_777, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _873 = clamp(dot(_511, half3(_777)), half(0.0), half(1.0));
    half _877 = clamp(dot(_511, normalize(half3(_527) + half3(_777))), half(0.0), half(1.0));
    half _919 = half(8192.0) * fma(half(-float(_873)), _669, _873 + _669);
    half _923 = half(1.0) / (half(params.facet_alpha) * _919);
    half _930 = half(2048.0) * half(params.facet_alpha);
    float3 _995 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _998 = dot(_995, _995);
    float3 _1003 = _995 * rsqrt(fast::max(_998, 9.9999999392252902907785028219223e-09));
    float _1007 = _998 * float(frame.punctualLights[1].positionFalloff.w);
    float _1012 = fast::clamp(fma(-_1007, _1007, 1.0), 0.0, 1.0);
    float _1031 = fast::clamp(fma(dot(-_1003, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1099 = clamp(dot(_511, half3(_1003)), half(0.0), half(1.0));
    half _1103 = clamp(dot(_511, normalize(half3(_527) + half3(_1003))), half(0.0), half(1.0));
    half _1145 = half(8192.0) * fma(half(-float(_1099)), _669, _1099 + _669);
    half _1149 = half(1.0) / (half(params.facet_alpha) * _1145);
    half3 _1185 = (fma(half4(_732).xyz, _725 * _687, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_725.x, max(_725.y, _725.z)))), _687, half(1.0))) + min((_725 * ((((fma(_923, _919, half(2.0)) * pow(max(fma(half(-float(_877)), _877, half(1.0)), half(0.0)), half(0.5) * (_923 * _919))) * half(0.15915493667125701904296875)) * (_873 * (_923 * _930))) * _691)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_786) * half(_786)) / fast::max(_772, 9.9999997473787516355514526367188e-05)) * half(_805)) * half(_805)), float3(65504.0))), half3(float3(65504.0)))) + min((_725 * ((((fma(_1149, _1145, half(2.0)) * pow(max(fma(half(-float(_1103)), _1103, half(1.0)), half(0.0)), half(0.5) * (_1149 * _1145))) * half(0.15915493667125701904296875)) * (_1099 * (_1149 * _930))) * _691)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1012) * half(_1012)) / fast::max(_998, 9.9999997473787516355514526367188e-05)) * half(_1031)) * half(_1031)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1185, half(1.0)));
    return out;
}

