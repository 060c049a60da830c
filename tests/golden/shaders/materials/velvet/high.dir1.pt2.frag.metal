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
    float4 _695 = facet_irradiance.sample(facet_irradianceSmplr, float3(_545), level(0.0));
    half _735 = max(dot(_545, half3(_561)), half(9.9999997473787516355514526367188e-05));
    float4 _740 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_735, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1558 = half4(_740);
    half _753 = _1558.z;
    half _755 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _753, half(1.0));
    half4 _1562 = half4(_740);
    half _760 = _1562.w;
    float4 _769 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_561), _545)), level(params.facet_sheenLod));
    half3 _593 = half4(frame.lightDirection).xyz;
    half _825 = dot(_545, _593);
    half _827 = clamp(_825, half(0.0), half(1.0));
    half _839 = clamp(dot(_545, normalize(half3(_561) + _593)), half(0.0), half(1.0));
    half _908 = half(8192.0) * fma(half(-float(_827)), _735, _827 + _735);
    half _912 = half(1.0) / (half(params.facet_alpha) * _908);
    half _919 = half(2048.0) * half(params.facet_alpha);
    float3 _983 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _986 = dot(_983, _983);
    float3 _991 = _983 * rsqrt(fast::max(_986, 9.9999999392252902907785028219223e-09));
    float _995 = _986 * float(frame.punctualLights[0].positionFalloff.w);
    float _1000 = fast::clamp(fma(-_995, _995, 1.0), 0.0, 1.0);
    float _1019 = fast::clamp(fma(dot(-_991, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1053 = dot(_545, half3(_991));
    half _1055 = clamp(_1053, half(0.0), half(1.0));
    half _1067 = clamp(dot(_545, normalize(half3(_561) + half3(_991))), half(0.0), half(1.0));
    half _1136 = half(8192.0) * fma(half(-float(_1055)), _735, _1055 + _735);
    half _1140 = half(1.0) / (half(params.facet_alpha) * _1136);
    half3 _1100 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1053 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1055), half3(float3(0.0)), half3(float3(1.0)))) * _755) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1140, _1136, half(2.0)) * pow(max(fma(half(-float(_1067)), _1067, half(1.0)), half(0.0)), half(0.5) * (_1140 * _1136))) * half(0.15915493667125701904296875)) * (_1055 * (_1140 * _919))) * _760))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1000) * half(_1000)) / fast::max(_986, 9.9999997473787516355514526367188e-05)) * half(_1019)) * half(_1019)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1175 = (fma(half4(_769).xyz, half3(float3(params.facet_sheenColor)) * _753, (half3(float3(params.facet_diffuseColor)) * half4(_695).xyz) * _755) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_825 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_827), half3(float3(0.0)), half3(float3(1.0)))) * _755) + (half3(float3(params.facet_sheenColor)) * ((((fma(_912, _908, half(2.0)) * pow(max(fma(half(-float(_839)), _839, half(1.0)), half(0.0)), half(0.5) * (_912 * _908))) * half(0.15915493667125701904296875)) * (_827 * (_912 * _919))) * _760))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1100;
    float3 _1211 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1214 = dot(_1211, _1211);
    float3 _1219 = _1211 * rsqrt(fast::max(_1214, 9.9999999392252902907785028219223e-09));
    float _1223 = _1214 * float(frame.punctualLights[1].positionFalloff.w);
    float _1228 = fast::clamp(fma(-_1223, _1223, 1.0), 0.0, 1.0);
    float _1247 = fast::clamp(fma(dot(-_1219, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1281 = dot(_545, half3(_1219));
    half _1283 = clamp(_1281, half(0.0), half(1.0));
    half _1295 = clamp(dot(_545, normalize(half3(_561) + half3(_1219))), half(0.0), half(1.0));
    half _1364 = half(8192.0) * fma(half(-float(_1283)), _735, _1283 + _735);
    half _1368 = half(1.0) / (half(params.facet_alpha) * _1364);
    half3 _1328 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1281 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1283), half3(float3(0.0)), half3(float3(1.0)))) * _755) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1368, _1364, half(2.0)) * pow(max(fma(half(-float(_1295)), _1295, half(1.0)), half(0.0)), half(0.5) * (_1368 * _1364))) * half(0.15915493667125701904296875)) * (_1283 * (_1368 * _919))) * _760))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1228) * half(_1228)) / fast::max(_1214, 9.9999997473787516355514526367188e-05)) * half(_1247)) * half(_1247)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1175 + _1328, half(1.0)));
    return out;
}

