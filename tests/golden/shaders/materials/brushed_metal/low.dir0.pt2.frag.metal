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
    half3 _551 = normalize(half3(in.v_normal));
    float3 _567 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _732 = reflect(-half3(_567), _551);
    float4 _768 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_551, half3(_567)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _797 = facet_environment.sample(facet_environmentSmplr, float3(_732), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _747 = mix(half4(_768).xxx, half4(_768).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_768).y) - half(1.0))));
    float3 _842 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _845 = dot(_842, _842);
    float3 _850 = _842 * rsqrt(fast::max(_845, 9.9999999392252902907785028219223e-09));
    float _854 = _845 * float(frame.punctualLights[0].positionFalloff.w);
    float _859 = fast::clamp(fma(-_854, _854, 1.0), 0.0, 1.0);
    float _878 = fast::clamp(fma(dot(-_850, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1010 = clamp(dot(_732, half3(_850)), half(0.0), half(1.0));
    half _1013 = _1010 * _1010;
    half4 _1438 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1013 * _1013, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1025 = _1438.x;
    float3 _1070 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1073 = dot(_1070, _1070);
    float3 _1078 = _1070 * rsqrt(fast::max(_1073, 9.9999999392252902907785028219223e-09));
    float _1082 = _1073 * float(frame.punctualLights[1].positionFalloff.w);
    float _1087 = fast::clamp(fma(-_1082, _1082, 1.0), 0.0, 1.0);
    float _1106 = fast::clamp(fma(dot(-_1078, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1238 = clamp(dot(_732, half3(_1078)), half(0.0), half(1.0));
    half _1241 = _1238 * _1238;
    half4 _1464 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1241 * _1241, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1253 = _1464.x;
    half3 _1262 = fma(half4(_797).xyz, _747, min((_747 * ((_1025 * _1025) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_859) * half(_859)) / fast::max(_845, 9.9999997473787516355514526367188e-05)) * half(_878)) * half(_878)), float3(65504.0))) * clamp(dot(_551, half3(_850)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_747 * ((_1253 * _1253) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1087) * half(_1087)) / fast::max(_1073, 9.9999997473787516355514526367188e-05)) * half(_1106)) * half(_1106)), float3(65504.0))) * clamp(dot(_551, half3(_1078)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1262, half(1.0)));
    return out;
}

