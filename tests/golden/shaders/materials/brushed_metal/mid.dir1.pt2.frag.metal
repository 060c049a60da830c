#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float anisotropy;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
    packed_float3 facet_f0;
    float facet_alpha;
    float facet_anisotropy;
    float facet_anisotropicBend;
    float2 facet_anisotropicAlpha;
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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _608 = normalize(half3(in.v_normal));
    float3 _614 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _843 = reflect(-half3(_614), _608);
    float4 _873 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_608, half3(_614)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    half3 _882 = mix(half4(_873).xxx, half4(_873).yyy, half3(float3(params.facet_f0)));
    float4 _892 = facet_environment.sample(facet_environmentSmplr, float3(_843), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _648 = half4(frame.lightDirection).xyz;
    half _1029 = clamp(dot(_843, _648), half(0.0), half(1.0));
    half _1032 = _1029 * _1029;
    half4 _1726 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1032 * _1032, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1044 = _1726.x;
    float3 _1103 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1106 = dot(_1103, _1103);
    float3 _1111 = _1103 * rsqrt(fast::max(_1106, 9.9999999392252902907785028219223e-09));
    float _1115 = _1106 * float(frame.punctualLights[0].positionFalloff.w);
    float _1120 = fast::clamp(fma(-_1115, _1115, 1.0), 0.0, 1.0);
    float _1139 = fast::clamp(fma(dot(-_1111, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1279 = clamp(dot(_843, half3(_1111)), half(0.0), half(1.0));
    half _1282 = _1279 * _1279;
    half4 _1751 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1282 * _1282, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1294 = _1751.x;
    float3 _1353 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1356 = dot(_1353, _1353);
    float3 _1361 = _1353 * rsqrt(fast::max(_1356, 9.9999999392252902907785028219223e-09));
    float _1365 = _1356 * float(frame.punctualLights[1].positionFalloff.w);
    float _1370 = fast::clamp(fma(-_1365, _1365, 1.0), 0.0, 1.0);
    float _1389 = fast::clamp(fma(dot(-_1361, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1529 = clamp(dot(_843, half3(_1361)), half(0.0), half(1.0));
    half _1532 = _1529 * _1529;
    half4 _1777 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1532 * _1532, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1544 = _1777.x;
    half3 _1567 = (fma(half4(_892).xyz, _882, min((_882 * ((_1044 * _1044) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_608, _648), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_882 * ((_1294 * _1294) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1120) * half(_1120)) / fast::max(_1106, 9.9999997473787516355514526367188e-05)) * half(_1139)) * half(_1139)), float3(65504.0))) * clamp(dot(_608, half3(_1111)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_882 * ((_1544 * _1544) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1370) * half(_1370)) / fast::max(_1356, 9.9999997473787516355514526367188e-05)) * half(_1389)) * half(_1389)), float3(65504.0))) * clamp(dot(_608, half3(_1361)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1567, half(1.0)));
    return out;
}

