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
    float4 _696 = facet_irradiance.sample(facet_irradianceSmplr, float3(_545), level(0.0));
    half _736 = max(dot(_545, half3(_561)), half(9.9999997473787516355514526367188e-05));
    float4 _741 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_736, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1559 = half4(_741);
    half _754 = _1559.z;
    half _756 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _754, half(1.0));
    half4 _1563 = half4(_741);
    half _761 = _1563.w;
    float4 _770 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_561), _545)), level(params.facet_sheenLod));
    half3 _593 = half4(frame.lightDirection).xyz;
    half _826 = dot(_545, _593);
    half _828 = clamp(_826, half(0.0), half(1.0));
    half _840 = clamp(dot(_545, normalize(half3(_561) + _593)), half(0.0), half(1.0));
    half _909 = half(8192.0) * fma(half(-float(_828)), _736, _828 + _736);
    half _913 = half(1.0) / (half(params.facet_alpha) * _909);
    half _920 = half(2048.0) * half(params.facet_alpha);
    float3 _984 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _987 = dot(_984, _984);
    float3 _992 = _984 * rsqrt(fast::max(_987, 9.9999999392252902907785028219223e-09));
    float _996 = _987 * float(frame.punctualLights[0].positionFalloff.w);
    float _1001 = fast::clamp(fma(-_996, _996, 1.0), 0.0, 1.0);
    float _1020 = fast::clamp(fma(dot(-_992, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1054 = dot(_545, half3(_992));
    half _1056 = clamp(_1054, half(0.0), half(1.0));
    half _1068 = clamp(dot(_545, normalize(half3(_561) + half3(_992))), half(0.0), half(1.0));
    half _1137 = half(8192.0) * fma(half(-float(_1056)), _736, _1056 + _736);
    half _1141 = half(1.0) / (half(params.facet_alpha) * _1137);
    half3 _1101 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1054 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1056), half3(float3(0.0)), half3(float3(1.0)))) * _756) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1141, _1137, half(2.0)) * pow(max(fma(half(-float(_1068)), _1068, half(1.0)), half(0.0)), half(0.5) * (_1141 * _1137))) * half(0.15915493667125701904296875)) * (_1056 * (_1141 * _920))) * _761))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1001) * half(_1001)) / fast::max(_987, 9.9999997473787516355514526367188e-05)) * half(_1020)) * half(_1020)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1176 = (fma(half4(_770).xyz, half3(float3(params.facet_sheenColor)) * _754, (half3(float3(params.facet_diffuseColor)) * half4(_696).xyz) * _756) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_826 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_828), half3(float3(0.0)), half3(float3(1.0)))) * _756) + (half3(float3(params.facet_sheenColor)) * ((((fma(_913, _909, half(2.0)) * pow(max(fma(half(-float(_840)), _840, half(1.0)), half(0.0)), half(0.5) * (_913 * _909))) * half(0.15915493667125701904296875)) * (_828 * (_913 * _920))) * _761))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1101;
    float3 _1212 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1215 = dot(_1212, _1212);
    float3 _1220 = _1212 * rsqrt(fast::max(_1215, 9.9999999392252902907785028219223e-09));
    float _1224 = _1215 * float(frame.punctualLights[1].positionFalloff.w);
    float _1229 = fast::clamp(fma(-_1224, _1224, 1.0), 0.0, 1.0);
    float _1248 = fast::clamp(fma(dot(-_1220, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1282 = dot(_545, half3(_1220));
    half _1284 = clamp(_1282, half(0.0), half(1.0));
    half _1296 = clamp(dot(_545, normalize(half3(_561) + half3(_1220))), half(0.0), half(1.0));
    half _1365 = half(8192.0) * fma(half(-float(_1284)), _736, _1284 + _736);
    half _1369 = half(1.0) / (half(params.facet_alpha) * _1365);
    half3 _1329 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1282 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1284), half3(float3(0.0)), half3(float3(1.0)))) * _756) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1369, _1365, half(2.0)) * pow(max(fma(half(-float(_1296)), _1296, half(1.0)), half(0.0)), half(0.5) * (_1369 * _1365))) * half(0.15915493667125701904296875)) * (_1284 * (_1369 * _920))) * _761))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1229) * half(_1229)) / fast::max(_1215, 9.9999997473787516355514526367188e-05)) * half(_1248)) * half(_1248)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1176 + _1329, half(1.0)));
    return out;
}

