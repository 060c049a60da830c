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
    half3 _753 = reflect(-half3(_567), _551);
    float4 _789 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_551, half3(_567)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _818 = facet_environment.sample(facet_environmentSmplr, float3(_753), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _768 = mix(half4(_789).xxx, half4(_789).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_789).y) - half(1.0))));
    half3 _604 = half4(frame.lightDirection).xyz;
    half _947 = clamp(dot(_753, _604), half(0.0), half(1.0));
    half _950 = _947 * _947;
    half4 _1592 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_950 * _950, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _962 = _1592.x;
    float3 _1007 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1010 = dot(_1007, _1007);
    float3 _1015 = _1007 * rsqrt(fast::max(_1010, 9.9999999392252902907785028219223e-09));
    float _1019 = _1010 * float(frame.punctualLights[0].positionFalloff.w);
    float _1024 = fast::clamp(fma(-_1019, _1019, 1.0), 0.0, 1.0);
    float _1043 = fast::clamp(fma(dot(-_1015, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1175 = clamp(dot(_753, half3(_1015)), half(0.0), half(1.0));
    half _1178 = _1175 * _1175;
    half4 _1617 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1178 * _1178, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1190 = _1617.x;
    float3 _1235 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1238 = dot(_1235, _1235);
    float3 _1243 = _1235 * rsqrt(fast::max(_1238, 9.9999999392252902907785028219223e-09));
    float _1247 = _1238 * float(frame.punctualLights[1].positionFalloff.w);
    float _1252 = fast::clamp(fma(-_1247, _1247, 1.0), 0.0, 1.0);
    float _1271 = fast::clamp(fma(dot(-_1243, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1403 = clamp(dot(_753, half3(_1243)), half(0.0), half(1.0));
    half _1406 = _1403 * _1403;
    half4 _1643 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1406 * _1406, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1418 = _1643.x;
    half3 _1427 = (fma(half4(_818).xyz, _768, min((_768 * ((_962 * _962) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_551, _604), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_768 * ((_1190 * _1190) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1024) * half(_1024)) / fast::max(_1010, 9.9999997473787516355514526367188e-05)) * half(_1043)) * half(_1043)), float3(65504.0))) * clamp(dot(_551, half3(_1015)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_768 * ((_1418 * _1418) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1252) * half(_1252)) / fast::max(_1238, 9.9999997473787516355514526367188e-05)) * half(_1271)) * half(_1271)), float3(65504.0))) * clamp(dot(_551, half3(_1243)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1427, half(1.0)));
    return out;
}

