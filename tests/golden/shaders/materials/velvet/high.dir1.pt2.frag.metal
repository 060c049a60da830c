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
    float4 _697 = facet_irradiance.sample(facet_irradianceSmplr, float3(_547), level(0.0));
    half _737 = max(dot(_547, half3(_563)), half(9.9999997473787516355514526367188e-05));
    float4 _742 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_737, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1560 = half4(_742);
    half _755 = _1560.z;
    half _757 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _755, half(1.0));
    half4 _1564 = half4(_742);
    half _762 = _1564.w;
    float4 _771 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_563), _547)), level(params.facet_sheenLod));
    half3 _595 = half4(frame.lightDirection).xyz;
    half _827 = dot(_547, _595);
    half _829 = clamp(_827, half(0.0), half(1.0));
    half _841 = clamp(dot(_547, normalize(half3(_563) + _595)), half(0.0), half(1.0));
    half _910 = half(8192.0) * fma(half(-float(_829)), _737, _829 + _737);
    half _914 = half(1.0) / (half(params.facet_alpha) * _910);
    half _921 = half(2048.0) * half(params.facet_alpha);
    float3 _985 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _988 = dot(_985, _985);
    float3 _993 = _985 * rsqrt(fast::max(_988, 9.9999999392252902907785028219223e-09));
    float _997 = _988 * float(frame.punctualLights[0].positionFalloff.w);
    float _1002 = fast::clamp(fma(-_997, _997, 1.0), 0.0, 1.0);
    float _1021 = fast::clamp(fma(dot(-_993, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1055 = dot(_547, half3(_993));
    half _1057 = clamp(_1055, half(0.0), half(1.0));
    half _1069 = clamp(dot(_547, normalize(half3(_563) + half3(_993))), half(0.0), half(1.0));
    half _1138 = half(8192.0) * fma(half(-float(_1057)), _737, _1057 + _737);
    half _1142 = half(1.0) / (half(params.facet_alpha) * _1138);
    half3 _1102 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1055 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1057), half3(float3(0.0)), half3(float3(1.0)))) * _757) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1142, _1138, half(2.0)) * pow(max(fma(half(-float(_1069)), _1069, half(1.0)), half(0.0)), half(0.5) * (_1142 * _1138))) * half(0.15915493667125701904296875)) * (_1057 * (_1142 * _921))) * _762))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1002) * half(_1002)) / fast::max(_988, 9.9999997473787516355514526367188e-05)) * half(_1021)) * half(_1021)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1177 = (fma(half4(_771).xyz, half3(float3(params.facet_sheenColor)) * _755, (half3(float3(params.facet_diffuseColor)) * half4(_697).xyz) * _757) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_827 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_829), half3(float3(0.0)), half3(float3(1.0)))) * _757) + (half3(float3(params.facet_sheenColor)) * ((((fma(_914, _910, half(2.0)) * pow(max(fma(half(-float(_841)), _841, half(1.0)), half(0.0)), half(0.5) * (_914 * _910))) * half(0.15915493667125701904296875)) * (_829 * (_914 * _921))) * _762))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1102;
    float3 _1213 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1216 = dot(_1213, _1213);
    float3 _1221 = _1213 * rsqrt(fast::max(_1216, 9.9999999392252902907785028219223e-09));
    float _1225 = _1216 * float(frame.punctualLights[1].positionFalloff.w);
    float _1230 = fast::clamp(fma(-_1225, _1225, 1.0), 0.0, 1.0);
    float _1249 = fast::clamp(fma(dot(-_1221, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1283 = dot(_547, half3(_1221));
    half _1285 = clamp(_1283, half(0.0), half(1.0));
    half _1297 = clamp(dot(_547, normalize(half3(_563) + half3(_1221))), half(0.0), half(1.0));
    half _1366 = half(8192.0) * fma(half(-float(_1285)), _737, _1285 + _737);
    half _1370 = half(1.0) / (half(params.facet_alpha) * _1366);
    half3 _1330 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1283 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1285), half3(float3(0.0)), half3(float3(1.0)))) * _757) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1370, _1366, half(2.0)) * pow(max(fma(half(-float(_1297)), _1297, half(1.0)), half(0.0)), half(0.5) * (_1370 * _1366))) * half(0.15915493667125701904296875)) * (_1285 * (_1370 * _921))) * _762))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1230) * half(_1230)) / fast::max(_1216, 9.9999997473787516355514526367188e-05)) * half(_1249)) * half(_1249)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1177 + _1330, half(1.0)));
    return out;
}

