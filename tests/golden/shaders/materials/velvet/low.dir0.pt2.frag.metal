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
    half3 _546 = normalize(half3(in.v_normal));
    float3 _562 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _680 = facet_irradiance.sample(facet_irradianceSmplr, float3(_546), level(0.0));
    half _720 = max(dot(_546, half3(_562)), half(9.9999997473787516355514526367188e-05));
    float4 _725 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_720, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1380 = half4(_725);
    half _738 = _1380.z;
    half _740 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _738, half(1.0));
    half4 _1384 = half4(_725);
    half _745 = _1384.w;
    float4 _754 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_562), _546)), level(params.facet_sheenLod));
    float3 _824 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _827 = dot(_824, _824);
    float3 _832 = _824 * rsqrt(fast::max(_827, 9.9999999392252902907785028219223e-09));
    float _836 = _827 * float(frame.punctualLights[0].positionFalloff.w);
    float _841 = fast::clamp(fma(-_836, _836, 1.0), 0.0, 1.0);
    float _860 = fast::clamp(fma(dot(-_832, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _894 = dot(_546, half3(_832));
    half _896 = clamp(_894, half(0.0), half(1.0));
    half _908 = clamp(dot(_546, normalize(half3(_562) + half3(_832))), half(0.0), half(1.0));
    half _977 = half(8192.0) * fma(half(-float(_896)), _720, _896 + _720);
    half _981 = half(1.0) / (half(params.facet_alpha) * _977);
    half _988 = half(2048.0) * half(params.facet_alpha);
    half3 _941 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_894 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_896), half3(float3(0.0)), half3(float3(1.0)))) * _740) + (half3(float3(params.facet_sheenColor)) * ((((fma(_981, _977, half(2.0)) * pow(max(fma(half(-float(_908)), _908, half(1.0)), half(0.0)), half(0.5) * (_981 * _977))) * half(0.15915493667125701904296875)) * (_896 * (_981 * _988))) * _745))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_841) * half(_841)) / fast::max(_827, 9.9999997473787516355514526367188e-05)) * half(_860)) * half(_860)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1052 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1055 = dot(_1052, _1052);
    float3 _1060 = _1052 * rsqrt(fast::max(_1055, 9.9999999392252902907785028219223e-09));
    float _1064 = _1055 * float(frame.punctualLights[1].positionFalloff.w);
    float _1069 = fast::clamp(fma(-_1064, _1064, 1.0), 0.0, 1.0);
    float _1088 = fast::clamp(fma(dot(-_1060, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1122 = dot(_546, half3(_1060));
    half _1124 = clamp(_1122, half(0.0), half(1.0));
    half _1136 = clamp(dot(_546, normalize(half3(_562) + half3(_1060))), half(0.0), half(1.0));
    half _1205 = half(8192.0) * fma(half(-float(_1124)), _720, _1124 + _720);
    half _1209 = half(1.0) / (half(params.facet_alpha) * _1205);
    half3 _1169 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1122 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1124), half3(float3(0.0)), half3(float3(1.0)))) * _740) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1209, _1205, half(2.0)) * pow(max(fma(half(-float(_1136)), _1136, half(1.0)), half(0.0)), half(0.5) * (_1209 * _1205))) * half(0.15915493667125701904296875)) * (_1124 * (_1209 * _988))) * _745))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1069) * half(_1069)) / fast::max(_1055, 9.9999997473787516355514526367188e-05)) * half(_1088)) * half(_1088)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_754).xyz, half3(float3(params.facet_sheenColor)) * _738, (half3(float3(params.facet_diffuseColor)) * half4(_680).xyz) * _740) + _941) + _1169, half(1.0)));
    return out;
}

