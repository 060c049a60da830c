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
    half3 _479 = normalize(half3(in.v_normal));
    float3 _495 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _658 = max(dot(_479, half3(_495)), half(9.9999997473787516355514526367188e-05));
    float4 _663 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_658, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _709 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1386 = half4(_663);
    half _676 = _1386.z;
    half4 _1390 = half4(_663);
    half _680 = _1390.w;
    float4 _716 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_495), _479)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _530 = half4(frame.lightDirection).xyz;
    half _742 = clamp(dot(_479, _530), half(0.0), half(1.0));
    half _756 = clamp(dot(_479, normalize(half3(_495) + _530)), half(0.0), half(1.0));
    half _814 = half(2.0) + (half(1.0) / half(params.facet_alpha));
    half _817 = half(0.5) / half(params.facet_alpha);
    float3 _873 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _876 = dot(_873, _873);
    float3 _881 = _873 * rsqrt(fast::max(_876, 9.9999999392252902907785028219223e-09));
    float _885 = _876 * float(frame.punctualLights[0].positionFalloff.w);
    float _890 = fast::clamp(fma(-_885, _885, 1.0), 0.0, 1.0);
    float _909 = fast::clamp(fma(dot(-_881, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _946 = clamp(dot(_479, half3(_881)), half(0.0), half(1.0));
    half _960 = clamp(dot(_479, normalize(half3(_495) + half3(_881))), half(0.0), half(1.0));
    float3 _1077 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1080 = dot(_1077, _1077);
    float3 _1085 = _1077 * rsqrt(fast::max(_1080, 9.9999999392252902907785028219223e-09));
    float _1089 = _1080 * float(frame.punctualLights[1].positionFalloff.w);
    float _1094 = fast::clamp(fma(-_1089, _1089, 1.0), 0.0, 1.0);
    float _1113 = fast::clamp(fma(dot(-_1085, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1150 = clamp(dot(_479, half3(_1085)), half(0.0), half(1.0));
    half _1164 = clamp(dot(_479, normalize(half3(_495) + half3(_1085))), half(0.0), half(1.0));
    half3 _1245 = ((fma(half4(_716).xyz, _709 * _676, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_709.x, max(_709.y, _709.z)))), _676, half(1.0))) + min((_709 * ((((_814 * pow(max(fma(half(-float(_756)), _756, half(1.0)), half(0.0)), _817)) * half(0.15915493667125701904296875)) * (_742 / (half(4.0) * fma(half(-float(_742)), _658, _742 + _658)))) * _680)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + min((_709 * ((((_814 * pow(max(fma(half(-float(_960)), _960, half(1.0)), half(0.0)), _817)) * half(0.15915493667125701904296875)) * (_946 / (half(4.0) * fma(half(-float(_946)), _658, _946 + _658)))) * _680)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_890) * half(_890)) / fast::max(_876, 9.9999997473787516355514526367188e-05)) * half(_909)) * half(_909)), float3(65504.0))), half3(float3(65504.0)))) + min((_709 * ((((_814 * pow(max(fma(half(-float(_1164)), _1164, half(1.0)), half(0.0)), _817)) * half(0.15915493667125701904296875)) * (_1150 / (half(4.0) * fma(half(-float(_1150)), _658, _1150 + _658)))) * _680)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1094) * half(_1094)) / fast::max(_1080, 9.9999997473787516355514526367188e-05)) * half(_1113)) * half(_1113)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1245, half(1.0)));
    return out;
}

