#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float facet_perceptualRoughness;
    char _m3_pad[12];
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _539 = normalize(half3(in.v_normal));
    float3 _555 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _715 = reflect(-half3(_555), _539);
    float4 _751 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_539, half3(_555)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _777 = facet_environment.sample(facet_environmentSmplr, float3(_715), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _730 = mix(half4(_751).xxx, half4(_751).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_751).y) - half(1.0))));
    float3 _822 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _825 = dot(_822, _822);
    float3 _830 = _822 * rsqrt(fast::max(_825, 9.9999999392252902907785028219223e-09));
    float _834 = _825 * float(frame.punctualLights[0].positionFalloff.w);
    float _839 = fast::clamp(fma(-_834, _834, 1.0), 0.0, 1.0);
    float _858 = fast::clamp(fma(dot(-_830, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _990 = clamp(dot(_715, half3(_830)), half(0.0), half(1.0));
    half _993 = _990 * _990;
    half4 _1406 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_993 * _993, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1005 = _1406.x;
    float3 _1050 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1053 = dot(_1050, _1050);
    float3 _1058 = _1050 * rsqrt(fast::max(_1053, 9.9999999392252902907785028219223e-09));
    float _1062 = _1053 * float(frame.punctualLights[1].positionFalloff.w);
    float _1067 = fast::clamp(fma(-_1062, _1062, 1.0), 0.0, 1.0);
    float _1086 = fast::clamp(fma(dot(-_1058, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1218 = clamp(dot(_715, half3(_1058)), half(0.0), half(1.0));
    half _1221 = _1218 * _1218;
    half4 _1432 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1221 * _1221, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1233 = _1432.x;
    half3 _1242 = fma(half4(_777).xyz, _730, min((_730 * ((_1005 * _1005) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_839) * half(_839)) / fast::max(_825, 9.9999997473787516355514526367188e-05)) * half(_858)) * half(_858)), float3(65504.0))) * clamp(dot(_539, half3(_830)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_730 * ((_1233 * _1233) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1067) * half(_1067)) / fast::max(_1053, 9.9999997473787516355514526367188e-05)) * half(_1086)) * half(_1086)), float3(65504.0))) * clamp(dot(_539, half3(_1058)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1242, half(1.0)));
    return out;
}

