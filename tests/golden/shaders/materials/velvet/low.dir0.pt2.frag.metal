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
    half3 _472 = normalize(half3(in.v_normal));
    float3 _488 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _633 = max(dot(_472, half3(_488)), half(9.9999997473787516355514526367188e-05));
    float4 _638 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_633, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _684 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1235 = half4(_638);
    half _651 = _1235.z;
    half4 _1239 = half4(_638);
    half _655 = _1239.w;
    float4 _691 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_488), _472)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _728 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _731 = dot(_728, _728);
    float3 _736 = _728 * rsqrt(fast::max(_731, 9.9999999392252902907785028219223e-09));
    float _740 = _731 * float(frame.punctualLights[0].positionFalloff.w);
    float _745 = fast::clamp(fma(-_740, _740, 1.0), 0.0, 1.0);
    float _764 = fast::clamp(fma(dot(-_736, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _801 = clamp(dot(_472, half3(_736)), half(0.0), half(1.0));
    half _815 = clamp(dot(_472, normalize(half3(_488) + half3(_736))), half(0.0), half(1.0));
    half _862 = half(8192.0) * fma(half(-float(_801)), _633, _801 + _633);
    half _866 = half(1.0) / (half(params.facet_alpha) * _862);
    half _873 = half(2048.0) * half(params.facet_alpha);
    float3 _931 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _934 = dot(_931, _931);
    float3 _939 = _931 * rsqrt(fast::max(_934, 9.9999999392252902907785028219223e-09));
    float _943 = _934 * float(frame.punctualLights[1].positionFalloff.w);
    float _948 = fast::clamp(fma(-_943, _943, 1.0), 0.0, 1.0);
    float _967 = fast::clamp(fma(dot(-_939, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1004 = clamp(dot(_472, half3(_939)), half(0.0), half(1.0));
    half _1018 = clamp(dot(_472, normalize(half3(_488) + half3(_939))), half(0.0), half(1.0));
    half _1065 = half(8192.0) * fma(half(-float(_1004)), _633, _1004 + _633);
    half _1069 = half(1.0) / (half(params.facet_alpha) * _1065);
    half3 _1098 = (fma(half4(_691).xyz, _684 * _651, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_684.x, max(_684.y, _684.z)))), _651, half(1.0))) + min((_684 * ((((fma(_866, _862, half(2.0)) * pow(max(fma(half(-float(_815)), _815, half(1.0)), half(0.0)), half(0.5) * (_866 * _862))) * half(0.15915493667125701904296875)) * (_801 * (_866 * _873))) * _655)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_745) * half(_745)) / fast::max(_731, 9.9999997473787516355514526367188e-05)) * half(_764)) * half(_764)), float3(65504.0))), half3(float3(65504.0)))) + min((_684 * ((((fma(_1069, _1065, half(2.0)) * pow(max(fma(half(-float(_1018)), _1018, half(1.0)), half(0.0)), half(0.5) * (_1069 * _1065))) * half(0.15915493667125701904296875)) * (_1004 * (_1069 * _873))) * _655)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_948) * half(_948)) / fast::max(_934, 9.9999997473787516355514526367188e-05)) * half(_967)) * half(_967)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1098, half(1.0)));
    return out;
}

