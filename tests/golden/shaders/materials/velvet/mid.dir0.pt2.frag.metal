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
    float4 _677 = facet_irradiance.sample(facet_irradianceSmplr, float3(_547), level(0.0));
    half _717 = max(dot(_547, half3(_563)), half(9.9999997473787516355514526367188e-05));
    float4 _722 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_717, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1377 = half4(_722);
    half _735 = _1377.z;
    half _737 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _735, half(1.0));
    half4 _1381 = half4(_722);
    half _742 = _1381.w;
    float4 _751 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_563), _547)), level(params.facet_sheenLod));
    float3 _821 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _824 = dot(_821, _821);
    float3 _829 = _821 * rsqrt(fast::max(_824, 9.9999999392252902907785028219223e-09));
    float _833 = _824 * float(frame.punctualLights[0].positionFalloff.w);
    float _838 = fast::clamp(fma(-_833, _833, 1.0), 0.0, 1.0);
    float _857 = fast::clamp(fma(dot(-_829, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _891 = dot(_547, half3(_829));
    half _893 = clamp(_891, half(0.0), half(1.0));
    half _905 = clamp(dot(_547, normalize(half3(_563) + half3(_829))), half(0.0), half(1.0));
    half _974 = half(8192.0) * fma(half(-float(_893)), _717, _893 + _717);
    half _978 = half(1.0) / (half(params.facet_alpha) * _974);
    half _985 = half(2048.0) * half(params.facet_alpha);
    half3 _938 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_891 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_893), half3(float3(0.0)), half3(float3(1.0)))) * _737) + (half3(float3(params.facet_sheenColor)) * ((((fma(_978, _974, half(2.0)) * pow(max(fma(half(-float(_905)), _905, half(1.0)), half(0.0)), half(0.5) * (_978 * _974))) * half(0.15915493667125701904296875)) * (_893 * (_978 * _985))) * _742))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_838) * half(_838)) / fast::max(_824, 9.9999997473787516355514526367188e-05)) * half(_857)) * half(_857)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1049 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1052 = dot(_1049, _1049);
    float3 _1057 = _1049 * rsqrt(fast::max(_1052, 9.9999999392252902907785028219223e-09));
    float _1061 = _1052 * float(frame.punctualLights[1].positionFalloff.w);
    float _1066 = fast::clamp(fma(-_1061, _1061, 1.0), 0.0, 1.0);
    float _1085 = fast::clamp(fma(dot(-_1057, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1119 = dot(_547, half3(_1057));
    half _1121 = clamp(_1119, half(0.0), half(1.0));
    half _1133 = clamp(dot(_547, normalize(half3(_563) + half3(_1057))), half(0.0), half(1.0));
    half _1202 = half(8192.0) * fma(half(-float(_1121)), _717, _1121 + _717);
    half _1206 = half(1.0) / (half(params.facet_alpha) * _1202);
    half3 _1166 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1119 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1121), half3(float3(0.0)), half3(float3(1.0)))) * _737) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1206, _1202, half(2.0)) * pow(max(fma(half(-float(_1133)), _1133, half(1.0)), half(0.0)), half(0.5) * (_1206 * _1202))) * half(0.15915493667125701904296875)) * (_1121 * (_1206 * _985))) * _742))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1066) * half(_1066)) / fast::max(_1052, 9.9999997473787516355514526367188e-05)) * half(_1085)) * half(_1085)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_751).xyz, half3(float3(params.facet_sheenColor)) * _735, (half3(float3(params.facet_diffuseColor)) * half4(_677).xyz) * _737) + _938) + _1166, half(1.0)));
    return out;
}

