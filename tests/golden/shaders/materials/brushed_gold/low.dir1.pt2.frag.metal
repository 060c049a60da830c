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
    half3 _543 = normalize(half3(in.v_normal));
    float3 _559 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _740 = reflect(-half3(_559), _543);
    float4 _776 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_543, half3(_559)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _805 = facet_environment.sample(facet_environmentSmplr, float3(_740), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _755 = mix(half4(_776).xxx, half4(_776).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_776).y) - half(1.0))));
    half3 _596 = half4(frame.lightDirection).xyz;
    half _934 = clamp(dot(_740, _596), half(0.0), half(1.0));
    half _937 = _934 * _934;
    half4 _1569 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_937 * _937, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _949 = _1569.x;
    float3 _994 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _997 = dot(_994, _994);
    float3 _1002 = _994 * rsqrt(fast::max(_997, 9.9999999392252902907785028219223e-09));
    float _1006 = _997 * float(frame.punctualLights[0].positionFalloff.w);
    float _1011 = fast::clamp(fma(-_1006, _1006, 1.0), 0.0, 1.0);
    float _1030 = fast::clamp(fma(dot(-_1002, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1162 = clamp(dot(_740, half3(_1002)), half(0.0), half(1.0));
    half _1165 = _1162 * _1162;
    half4 _1594 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1165 * _1165, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1177 = _1594.x;
    float3 _1222 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1225 = dot(_1222, _1222);
    float3 _1230 = _1222 * rsqrt(fast::max(_1225, 9.9999999392252902907785028219223e-09));
    float _1234 = _1225 * float(frame.punctualLights[1].positionFalloff.w);
    float _1239 = fast::clamp(fma(-_1234, _1234, 1.0), 0.0, 1.0);
    float _1258 = fast::clamp(fma(dot(-_1230, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1390 = clamp(dot(_740, half3(_1230)), half(0.0), half(1.0));
    half _1393 = _1390 * _1390;
    half4 _1620 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1393 * _1393, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1405 = _1620.x;
    half3 _1414 = (fma(half4(_805).xyz, _755, min((_755 * ((_949 * _949) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_543, _596), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_755 * ((_1177 * _1177) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1011) * half(_1011)) / fast::max(_997, 9.9999997473787516355514526367188e-05)) * half(_1030)) * half(_1030)), float3(65504.0))) * clamp(dot(_543, half3(_1002)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_755 * ((_1405 * _1405) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1239) * half(_1239)) / fast::max(_1225, 9.9999997473787516355514526367188e-05)) * half(_1258)) * half(_1258)), float3(65504.0))) * clamp(dot(_543, half3(_1230)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1414, half(1.0)));
    return out;
}

