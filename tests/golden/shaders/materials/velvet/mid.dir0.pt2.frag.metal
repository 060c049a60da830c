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
    char _m8_pad[12];
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
    half3 _545 = normalize(half3(in.v_normal));
    float3 _561 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _675 = facet_irradiance.sample(facet_irradianceSmplr, float3(_545), level(0.0));
    half _715 = max(dot(_545, half3(_561)), half(9.9999997473787516355514526367188e-05));
    float4 _720 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_715, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1375 = half4(_720);
    half _733 = _1375.z;
    half _735 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _733, half(1.0));
    half4 _1379 = half4(_720);
    half _740 = _1379.w;
    float4 _749 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_561), _545)), level(params.facet_sheenLod));
    float3 _819 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _822 = dot(_819, _819);
    float3 _827 = _819 * rsqrt(fast::max(_822, 9.9999999392252902907785028219223e-09));
    float _831 = _822 * float(frame.punctualLights[0].positionFalloff.w);
    float _836 = fast::clamp(fma(-_831, _831, 1.0), 0.0, 1.0);
    float _855 = fast::clamp(fma(dot(-_827, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _889 = dot(_545, half3(_827));
    half _891 = clamp(_889, half(0.0), half(1.0));
    half _903 = clamp(dot(_545, normalize(half3(_561) + half3(_827))), half(0.0), half(1.0));
    half _972 = half(8192.0) * fma(half(-float(_891)), _715, _891 + _715);
    half _976 = half(1.0) / (half(params.facet_alpha) * _972);
    half _983 = half(2048.0) * half(params.facet_alpha);
    half3 _936 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_889 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_891), half3(float3(0.0)), half3(float3(1.0)))) * _735) + (half3(float3(params.facet_sheenColor)) * ((((fma(_976, _972, half(2.0)) * pow(max(fma(half(-float(_903)), _903, half(1.0)), half(0.0)), half(0.5) * (_976 * _972))) * half(0.15915493667125701904296875)) * (_891 * (_976 * _983))) * _740))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_836) * half(_836)) / fast::max(_822, 9.9999997473787516355514526367188e-05)) * half(_855)) * half(_855)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1047 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1050 = dot(_1047, _1047);
    float3 _1055 = _1047 * rsqrt(fast::max(_1050, 9.9999999392252902907785028219223e-09));
    float _1059 = _1050 * float(frame.punctualLights[1].positionFalloff.w);
    float _1064 = fast::clamp(fma(-_1059, _1059, 1.0), 0.0, 1.0);
    float _1083 = fast::clamp(fma(dot(-_1055, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1117 = dot(_545, half3(_1055));
    half _1119 = clamp(_1117, half(0.0), half(1.0));
    half _1131 = clamp(dot(_545, normalize(half3(_561) + half3(_1055))), half(0.0), half(1.0));
    half _1200 = half(8192.0) * fma(half(-float(_1119)), _715, _1119 + _715);
    half _1204 = half(1.0) / (half(params.facet_alpha) * _1200);
    half3 _1164 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1117 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1119), half3(float3(0.0)), half3(float3(1.0)))) * _735) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1204, _1200, half(2.0)) * pow(max(fma(half(-float(_1131)), _1131, half(1.0)), half(0.0)), half(0.5) * (_1204 * _1200))) * half(0.15915493667125701904296875)) * (_1119 * (_1204 * _983))) * _740))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1064) * half(_1064)) / fast::max(_1050, 9.9999997473787516355514526367188e-05)) * half(_1083)) * half(_1083)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_749).xyz, half3(float3(params.facet_sheenColor)) * _733, (half3(float3(params.facet_diffuseColor)) * half4(_675).xyz) * _735) + _936) + _1164, half(1.0)));
    return out;
}

