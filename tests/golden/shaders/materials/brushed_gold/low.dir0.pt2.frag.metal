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
    half3 _545 = normalize(half3(in.v_normal));
    float3 _561 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _721 = reflect(-half3(_561), _545);
    float4 _757 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_545, half3(_561)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _788 = facet_environment.sample(facet_environmentSmplr, float3(_721), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _736 = mix(half4(_757).xxx, half4(_757).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_757).y) - half(1.0))));
    float3 _833 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _836 = dot(_833, _833);
    float3 _841 = _833 * rsqrt(fast::max(_836, 9.9999999392252902907785028219223e-09));
    float _845 = _836 * float(frame.punctualLights[0].positionFalloff.w);
    float _850 = fast::clamp(fma(-_845, _845, 1.0), 0.0, 1.0);
    float _869 = fast::clamp(fma(dot(-_841, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1001 = clamp(dot(_721, half3(_841)), half(0.0), half(1.0));
    half _1004 = _1001 * _1001;
    half4 _1419 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1004 * _1004, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1016 = _1419.x;
    float3 _1061 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1064 = dot(_1061, _1061);
    float3 _1069 = _1061 * rsqrt(fast::max(_1064, 9.9999999392252902907785028219223e-09));
    float _1073 = _1064 * float(frame.punctualLights[1].positionFalloff.w);
    float _1078 = fast::clamp(fma(-_1073, _1073, 1.0), 0.0, 1.0);
    float _1097 = fast::clamp(fma(dot(-_1069, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1229 = clamp(dot(_721, half3(_1069)), half(0.0), half(1.0));
    half _1232 = _1229 * _1229;
    half4 _1445 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1232 * _1232, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1244 = _1445.x;
    half3 _1253 = fma(half4(_788).xyz, _736, min((_736 * ((_1016 * _1016) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_850) * half(_850)) / fast::max(_836, 9.9999997473787516355514526367188e-05)) * half(_869)) * half(_869)), float3(65504.0))) * clamp(dot(_545, half3(_841)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_736 * ((_1244 * _1244) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1078) * half(_1078)) / fast::max(_1064, 9.9999997473787516355514526367188e-05)) * half(_1097)) * half(_1097)), float3(65504.0))) * clamp(dot(_545, half3(_1069)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1253, half(1.0)));
    return out;
}

