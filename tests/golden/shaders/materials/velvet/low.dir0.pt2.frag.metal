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
    half3 _548 = normalize(half3(in.v_normal));
    float3 _564 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _682 = facet_irradiance.sample(facet_irradianceSmplr, float3(_548), level(0.0));
    half _722 = max(dot(_548, half3(_564)), half(9.9999997473787516355514526367188e-05));
    float4 _727 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_722, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1382 = half4(_727);
    half _740 = _1382.z;
    half _742 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _740, half(1.0));
    half4 _1386 = half4(_727);
    half _747 = _1386.w;
    float4 _756 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_564), _548)), level(params.facet_sheenLod));
    float3 _826 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _829 = dot(_826, _826);
    float3 _834 = _826 * rsqrt(fast::max(_829, 9.9999999392252902907785028219223e-09));
    float _838 = _829 * float(frame.punctualLights[0].positionFalloff.w);
    float _843 = fast::clamp(fma(-_838, _838, 1.0), 0.0, 1.0);
    float _862 = fast::clamp(fma(dot(-_834, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _896 = dot(_548, half3(_834));
    half _898 = clamp(_896, half(0.0), half(1.0));
    half _910 = clamp(dot(_548, normalize(half3(_564) + half3(_834))), half(0.0), half(1.0));
    half _979 = half(8192.0) * fma(half(-float(_898)), _722, _898 + _722);
    half _983 = half(1.0) / (half(params.facet_alpha) * _979);
    half _990 = half(2048.0) * half(params.facet_alpha);
    half3 _943 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_896 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_898), half3(float3(0.0)), half3(float3(1.0)))) * _742) + (half3(float3(params.facet_sheenColor)) * ((((fma(_983, _979, half(2.0)) * pow(max(fma(half(-float(_910)), _910, half(1.0)), half(0.0)), half(0.5) * (_983 * _979))) * half(0.15915493667125701904296875)) * (_898 * (_983 * _990))) * _747))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_843) * half(_843)) / fast::max(_829, 9.9999997473787516355514526367188e-05)) * half(_862)) * half(_862)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1054 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1057 = dot(_1054, _1054);
    float3 _1062 = _1054 * rsqrt(fast::max(_1057, 9.9999999392252902907785028219223e-09));
    float _1066 = _1057 * float(frame.punctualLights[1].positionFalloff.w);
    float _1071 = fast::clamp(fma(-_1066, _1066, 1.0), 0.0, 1.0);
    float _1090 = fast::clamp(fma(dot(-_1062, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1124 = dot(_548, half3(_1062));
    half _1126 = clamp(_1124, half(0.0), half(1.0));
    half _1138 = clamp(dot(_548, normalize(half3(_564) + half3(_1062))), half(0.0), half(1.0));
    half _1207 = half(8192.0) * fma(half(-float(_1126)), _722, _1126 + _722);
    half _1211 = half(1.0) / (half(params.facet_alpha) * _1207);
    half3 _1171 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1124 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1126), half3(float3(0.0)), half3(float3(1.0)))) * _742) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1211, _1207, half(2.0)) * pow(max(fma(half(-float(_1138)), _1138, half(1.0)), half(0.0)), half(0.5) * (_1211 * _1207))) * half(0.15915493667125701904296875)) * (_1126 * (_1211 * _990))) * _747))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1071) * half(_1071)) / fast::max(_1057, 9.9999997473787516355514526367188e-05)) * half(_1090)) * half(_1090)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_756).xyz, half3(float3(params.facet_sheenColor)) * _740, (half3(float3(params.facet_diffuseColor)) * half4(_682).xyz) * _742) + _943) + _1171, half(1.0)));
    return out;
}

