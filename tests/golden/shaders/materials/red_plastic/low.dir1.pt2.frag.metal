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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _536 = normalize(half3(in.v_normal));
    float3 _552 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _731 = reflect(-half3(_552), _536);
    float4 _767 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_536, half3(_552)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _793 = facet_environment.sample(facet_environmentSmplr, float3(_731), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _746 = mix(half4(_767).xxx, half4(_767).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_767).y) - half(1.0))));
    half3 _589 = half4(frame.lightDirection).xyz;
    half _922 = clamp(dot(_731, _589), half(0.0), half(1.0));
    half _925 = _922 * _922;
    half4 _1543 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_925 * _925, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _937 = _1543.x;
    float3 _982 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _985 = dot(_982, _982);
    float3 _990 = _982 * rsqrt(fast::max(_985, 9.9999999392252902907785028219223e-09));
    float _994 = _985 * float(frame.punctualLights[0].positionFalloff.w);
    float _999 = fast::clamp(fma(-_994, _994, 1.0), 0.0, 1.0);
    float _1018 = fast::clamp(fma(dot(-_990, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1150 = clamp(dot(_731, half3(_990)), half(0.0), half(1.0));
    half _1153 = _1150 * _1150;
    half4 _1568 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1153 * _1153, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1165 = _1568.x;
    float3 _1210 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1213 = dot(_1210, _1210);
    float3 _1218 = _1210 * rsqrt(fast::max(_1213, 9.9999999392252902907785028219223e-09));
    float _1222 = _1213 * float(frame.punctualLights[1].positionFalloff.w);
    float _1227 = fast::clamp(fma(-_1222, _1222, 1.0), 0.0, 1.0);
    float _1246 = fast::clamp(fma(dot(-_1218, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1378 = clamp(dot(_731, half3(_1218)), half(0.0), half(1.0));
    half _1381 = _1378 * _1378;
    half4 _1594 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1381 * _1381, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1393 = _1594.x;
    half3 _1402 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_793).xyz * _746) + min((_746 * ((_937 * _937) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_536, _589), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_746 * ((_1165 * _1165) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_999) * half(_999)) / fast::max(_985, 9.9999997473787516355514526367188e-05)) * half(_1018)) * half(_1018)), float3(65504.0))) * clamp(dot(_536, half3(_990)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_746 * ((_1393 * _1393) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1227) * half(_1227)) / fast::max(_1213, 9.9999997473787516355514526367188e-05)) * half(_1246)) * half(_1246)), float3(65504.0))) * clamp(dot(_536, half3(_1218)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1402, half(1.0)));
    return out;
}

