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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
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
    half3 _547 = normalize(half3(in.v_normal));
    float3 _563 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _676 = facet_irradiance.sample(facet_irradianceSmplr, float3(_547), level(0.0));
    half _716 = max(dot(_547, half3(_563)), half(9.9999997473787516355514526367188e-05));
    float4 _721 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_716, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1376 = half4(_721);
    half _734 = _1376.z;
    half _736 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _734, half(1.0));
    half4 _1380 = half4(_721);
    half _741 = _1380.w;
    float4 _750 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_563), _547)), level(params.facet_sheenLod));
    float3 _820 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _823 = dot(_820, _820);
    float3 _828 = _820 * rsqrt(fast::max(_823, 9.9999999392252902907785028219223e-09));
    float _832 = _823 * float(frame.punctualLights[0].positionFalloff.w);
    float _837 = fast::clamp(fma(-_832, _832, 1.0), 0.0, 1.0);
    float _856 = fast::clamp(fma(dot(-_828, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _890 = dot(_547, half3(_828));
    half _892 = clamp(_890, half(0.0), half(1.0));
    half _904 = clamp(dot(_547, normalize(half3(_563) + half3(_828))), half(0.0), half(1.0));
    half _973 = half(8192.0) * fma(half(-float(_892)), _716, _892 + _716);
    half _977 = half(1.0) / (half(params.facet_alpha) * _973);
    half _984 = half(2048.0) * half(params.facet_alpha);
    half3 _937 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_890 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_892), half3(float3(0.0)), half3(float3(1.0)))) * _736) + (half3(float3(params.facet_sheenColor)) * ((((fma(_977, _973, half(2.0)) * pow(max(fma(half(-float(_904)), _904, half(1.0)), half(0.0)), half(0.5) * (_977 * _973))) * half(0.15915493667125701904296875)) * (_892 * (_977 * _984))) * _741))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_837) * half(_837)) / fast::max(_823, 9.9999997473787516355514526367188e-05)) * half(_856)) * half(_856)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1048 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1051 = dot(_1048, _1048);
    float3 _1056 = _1048 * rsqrt(fast::max(_1051, 9.9999999392252902907785028219223e-09));
    float _1060 = _1051 * float(frame.punctualLights[1].positionFalloff.w);
    float _1065 = fast::clamp(fma(-_1060, _1060, 1.0), 0.0, 1.0);
    float _1084 = fast::clamp(fma(dot(-_1056, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1118 = dot(_547, half3(_1056));
    half _1120 = clamp(_1118, half(0.0), half(1.0));
    half _1132 = clamp(dot(_547, normalize(half3(_563) + half3(_1056))), half(0.0), half(1.0));
    half _1201 = half(8192.0) * fma(half(-float(_1120)), _716, _1120 + _716);
    half _1205 = half(1.0) / (half(params.facet_alpha) * _1201);
    half3 _1165 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1118 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1120), half3(float3(0.0)), half3(float3(1.0)))) * _736) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1205, _1201, half(2.0)) * pow(max(fma(half(-float(_1132)), _1132, half(1.0)), half(0.0)), half(0.5) * (_1205 * _1201))) * half(0.15915493667125701904296875)) * (_1120 * (_1205 * _984))) * _741))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1065) * half(_1065)) / fast::max(_1051, 9.9999997473787516355514526367188e-05)) * half(_1084)) * half(_1084)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_750).xyz, half3(float3(params.facet_sheenColor)) * _734, (half3(float3(params.facet_diffuseColor)) * half4(_676).xyz) * _736) + _937) + _1165, half(1.0)));
    return out;
}

