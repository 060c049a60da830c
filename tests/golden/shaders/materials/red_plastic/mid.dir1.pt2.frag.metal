#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    packed_float3 facet_f0;
    float facet_alpha;
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    half3 _536 = normalize(half3(in.v_normal));
    float3 _552 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _755 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_536, half3(_552)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _734 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_552), _536)), level(params.facet_environmentLod));
    half3 _589 = half4(frame.lightDirection).xyz;
    half3 _824 = half3(_552) + _589;
    half3 _834 = _824 * (half(64.0) * rsqrt(dot(_824, _824)));
    half _843 = clamp(dot(_589, _834) * half(0.015625), half(0.0), half(1.0));
    half _961 = max(_843 * _843, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _990 = half4(cross(_536, _834), half(params.facet_alpha) * clamp(dot(_536, _834), half(0.0), half(64.0)));
    half _971 = half(params.facet_ggxAlphaScaled) / (dot(_990, _990) * _961);
    float3 _1034 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1037 = dot(_1034, _1034);
    float3 _1042 = _1034 * rsqrt(fast::max(_1037, 9.9999999392252902907785028219223e-09));
    float _1046 = _1037 * float(frame.punctualLights[0].positionFalloff.w);
    float _1051 = fast::clamp(fma(-_1046, _1046, 1.0), 0.0, 1.0);
    float _1070 = fast::clamp(fma(dot(-_1042, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1134 = half3(_552) + half3(_1042);
    half3 _1144 = _1134 * (half(64.0) * rsqrt(dot(_1134, _1134)));
    half _1153 = clamp(dot(half3(_1042), _1144) * half(0.015625), half(0.0), half(1.0));
    half _1271 = max(_1153 * _1153, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1300 = half4(cross(_536, _1144), half(params.facet_alpha) * clamp(dot(_536, _1144), half(0.0), half(64.0)));
    half _1281 = half(params.facet_ggxAlphaScaled) / (dot(_1300, _1300) * _1271);
    float3 _1344 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1347 = dot(_1344, _1344);
    float3 _1352 = _1344 * rsqrt(fast::max(_1347, 9.9999999392252902907785028219223e-09));
    float _1356 = _1347 * float(frame.punctualLights[1].positionFalloff.w);
    float _1361 = fast::clamp(fma(-_1356, _1356, 1.0), 0.0, 1.0);
    float _1380 = fast::clamp(fma(dot(-_1352, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1444 = half3(_552) + half3(_1352);
    half3 _1454 = _1444 * (half(64.0) * rsqrt(dot(_1444, _1444)));
    half _1463 = clamp(dot(half3(_1352), _1454) * half(0.015625), half(0.0), half(1.0));
    half _1581 = max(_1463 * _1463, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1610 = half4(cross(_536, _1454), half(params.facet_alpha) * clamp(dot(_536, _1454), half(0.0), half(64.0)));
    half _1591 = half(params.facet_ggxAlphaScaled) / (dot(_1610, _1610) * _1581);
    half3 _1618 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_734).xyz * mix(half4(_755).xxx, half4(_755).yyy, half3(float3(params.facet_f0)))) + min((half3(float3(params.facet_f0)) * half4(frame.lightColor).xyz) * (min((_971 * _971) * _961, half(65504.0)) * clamp(dot(_536, _589), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((half3(float3(params.facet_f0)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1051) * half(_1051)) / fast::max(_1037, 9.9999997473787516355514526367188e-05)) * half(_1070)) * half(_1070)), float3(65504.0)))) * (min((_1281 * _1281) * _1271, half(65504.0)) * clamp(dot(_536, half3(_1042)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((half3(float3(params.facet_f0)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1361) * half(_1361)) / fast::max(_1347, 9.9999997473787516355514526367188e-05)) * half(_1380)) * half(_1380)), float3(65504.0)))) * (min((_1591 * _1591) * _1581, half(65504.0)) * clamp(dot(_536, half3(_1352)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1618, half(1.0)));
    return out;
}

