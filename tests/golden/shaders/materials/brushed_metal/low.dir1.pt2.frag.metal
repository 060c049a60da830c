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
    half3 _547 = normalize(half3(in.v_normal));
    float3 _563 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _749 = reflect(-half3(_563), _547);
    float4 _785 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_547, half3(_563)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _811 = facet_environment.sample(facet_environmentSmplr, float3(_749), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _764 = mix(half4(_785).xxx, half4(_785).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_785).y) - half(1.0))));
    half3 _600 = half4(frame.lightDirection).xyz;
    half _940 = clamp(dot(_749, _600), half(0.0), half(1.0));
    half _943 = _940 * _940;
    half4 _1583 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_943 * _943, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _955 = _1583.x;
    float3 _1000 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1003 = dot(_1000, _1000);
    float3 _1008 = _1000 * rsqrt(fast::max(_1003, 9.9999999392252902907785028219223e-09));
    float _1012 = _1003 * float(frame.punctualLights[0].positionFalloff.w);
    float _1017 = fast::clamp(fma(-_1012, _1012, 1.0), 0.0, 1.0);
    float _1036 = fast::clamp(fma(dot(-_1008, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1168 = clamp(dot(_749, half3(_1008)), half(0.0), half(1.0));
    half _1171 = _1168 * _1168;
    half4 _1608 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1171 * _1171, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1183 = _1608.x;
    float3 _1228 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1231 = dot(_1228, _1228);
    float3 _1236 = _1228 * rsqrt(fast::max(_1231, 9.9999999392252902907785028219223e-09));
    float _1240 = _1231 * float(frame.punctualLights[1].positionFalloff.w);
    float _1245 = fast::clamp(fma(-_1240, _1240, 1.0), 0.0, 1.0);
    float _1264 = fast::clamp(fma(dot(-_1236, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1396 = clamp(dot(_749, half3(_1236)), half(0.0), half(1.0));
    half _1399 = _1396 * _1396;
    half4 _1634 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1399 * _1399, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1411 = _1634.x;
    half3 _1420 = (fma(half4(_811).xyz, _764, min((_764 * ((_955 * _955) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_547, _600), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_764 * ((_1183 * _1183) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1017) * half(_1017)) / fast::max(_1003, 9.9999997473787516355514526367188e-05)) * half(_1036)) * half(_1036)), float3(65504.0))) * clamp(dot(_547, half3(_1008)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_764 * ((_1411 * _1411) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1245) * half(_1245)) / fast::max(_1231, 9.9999997473787516355514526367188e-05)) * half(_1264)) * half(_1264)), float3(65504.0))) * clamp(dot(_547, half3(_1236)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1420, half(1.0)));
    return out;
}

