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
    float4 _698 = facet_irradiance.sample(facet_irradianceSmplr, float3(_547), level(0.0));
    half _738 = max(dot(_547, half3(_563)), half(9.9999997473787516355514526367188e-05));
    float4 _743 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_738, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1561 = half4(_743);
    half _756 = _1561.z;
    half _758 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _756, half(1.0));
    half4 _1565 = half4(_743);
    half _763 = _1565.w;
    float4 _772 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_563), _547)), level(params.facet_sheenLod));
    half3 _595 = half4(frame.lightDirection).xyz;
    half _828 = dot(_547, _595);
    half _830 = clamp(_828, half(0.0), half(1.0));
    half _842 = clamp(dot(_547, normalize(half3(_563) + _595)), half(0.0), half(1.0));
    half _911 = half(8192.0) * fma(half(-float(_830)), _738, _830 + _738);
    half _915 = half(1.0) / (half(params.facet_alpha) * _911);
    half _922 = half(2048.0) * half(params.facet_alpha);
    float3 _986 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _989 = dot(_986, _986);
    float3 _994 = _986 * rsqrt(fast::max(_989, 9.9999999392252902907785028219223e-09));
    float _998 = _989 * float(frame.punctualLights[0].positionFalloff.w);
    float _1003 = fast::clamp(fma(-_998, _998, 1.0), 0.0, 1.0);
    float _1022 = fast::clamp(fma(dot(-_994, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1056 = dot(_547, half3(_994));
    half _1058 = clamp(_1056, half(0.0), half(1.0));
    half _1070 = clamp(dot(_547, normalize(half3(_563) + half3(_994))), half(0.0), half(1.0));
    half _1139 = half(8192.0) * fma(half(-float(_1058)), _738, _1058 + _738);
    half _1143 = half(1.0) / (half(params.facet_alpha) * _1139);
    half3 _1103 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1056 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1058), half3(float3(0.0)), half3(float3(1.0)))) * _758) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1143, _1139, half(2.0)) * pow(max(fma(half(-float(_1070)), _1070, half(1.0)), half(0.0)), half(0.5) * (_1143 * _1139))) * half(0.15915493667125701904296875)) * (_1058 * (_1143 * _922))) * _763))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1003) * half(_1003)) / fast::max(_989, 9.9999997473787516355514526367188e-05)) * half(_1022)) * half(_1022)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1178 = (fma(half4(_772).xyz, half3(float3(params.facet_sheenColor)) * _756, (half3(float3(params.facet_diffuseColor)) * half4(_698).xyz) * _758) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_828 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_830), half3(float3(0.0)), half3(float3(1.0)))) * _758) + (half3(float3(params.facet_sheenColor)) * ((((fma(_915, _911, half(2.0)) * pow(max(fma(half(-float(_842)), _842, half(1.0)), half(0.0)), half(0.5) * (_915 * _911))) * half(0.15915493667125701904296875)) * (_830 * (_915 * _922))) * _763))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1103;
    float3 _1214 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1217 = dot(_1214, _1214);
    float3 _1222 = _1214 * rsqrt(fast::max(_1217, 9.9999999392252902907785028219223e-09));
    float _1226 = _1217 * float(frame.punctualLights[1].positionFalloff.w);
    float _1231 = fast::clamp(fma(-_1226, _1226, 1.0), 0.0, 1.0);
    float _1250 = fast::clamp(fma(dot(-_1222, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1284 = dot(_547, half3(_1222));
    half _1286 = clamp(_1284, half(0.0), half(1.0));
    half _1298 = clamp(dot(_547, normalize(half3(_563) + half3(_1222))), half(0.0), half(1.0));
    half _1367 = half(8192.0) * fma(half(-float(_1286)), _738, _1286 + _738);
    half _1371 = half(1.0) / (half(params.facet_alpha) * _1367);
    half3 _1331 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1284 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1286), half3(float3(0.0)), half3(float3(1.0)))) * _758) + (half3(float3(params.facet_sheenColor)) * ((((fma(_1371, _1367, half(2.0)) * pow(max(fma(half(-float(_1298)), _1298, half(1.0)), half(0.0)), half(0.5) * (_1371 * _1367))) * half(0.15915493667125701904296875)) * (_1286 * (_1371 * _922))) * _763))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1231) * half(_1231)) / fast::max(_1217, 9.9999997473787516355514526367188e-05)) * half(_1250)) * half(_1250)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1178 + _1331, half(1.0)));
    return out;
}

