#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 glazeColor;
    packed_float3 clayColor;
    float glazeRoughness;
    float clayRoughness;
    float bandsPerUnit;
    float bandSharpness;
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
    half3 _597 = normalize(half3(in.v_normal));
    float3 _613 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _762 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _863 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _762)), half(0.0), half(1.0));
    half _880 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _762)), half(0.08900000154972076416015625), half(1.0));
    half3 _832 = reflect(-half3(_613), _597);
    float4 _887 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_597, half3(_613)), half(9.9999997473787516355514526367188e-05)), _880)), level(0.0));
    half3 _896 = mix(half4(_887).xxx, half4(_887).yyy, half3((half(0.1599999964237213134765625) * _863) * _863));
    float4 _906 = facet_environment.sample(facet_environmentSmplr, float3(_832), level(_880 * (half(4.0) * (half(2.0) - _880))));
    half3 _650 = half4(frame.lightDirection).xyz;
    half _1070 = clamp(dot(_832, _650), half(0.0), half(1.0));
    half _1073 = _1070 * _1070;
    half4 _1792 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1073 * _1073, _880), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1085 = _1792.x;
    float3 _1130 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1133 = dot(_1130, _1130);
    float3 _1138 = _1130 * rsqrt(fast::max(_1133, 9.9999999392252902907785028219223e-09));
    float _1142 = _1133 * float(frame.punctualLights[0].positionFalloff.w);
    float _1147 = fast::clamp(fma(-_1142, _1142, 1.0), 0.0, 1.0);
    float _1166 = fast::clamp(fma(dot(-_1138, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1333 = clamp(dot(_832, half3(_1138)), half(0.0), half(1.0));
    half _1336 = _1333 * _1333;
    half4 _1816 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1336 * _1336, _880), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1348 = _1816.x;
    float3 _1393 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1396 = dot(_1393, _1393);
    float3 _1401 = _1393 * rsqrt(fast::max(_1396, 9.9999999392252902907785028219223e-09));
    float _1405 = _1396 * float(frame.punctualLights[1].positionFalloff.w);
    float _1410 = fast::clamp(fma(-_1405, _1405, 1.0), 0.0, 1.0);
    float _1429 = fast::clamp(fma(dot(-_1401, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1596 = clamp(dot(_832, half3(_1401)), half(0.0), half(1.0));
    half _1599 = _1596 * _1596;
    half4 _1841 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1599 * _1599, _880), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1611 = _1841.x;
    half3 _1620 = ((fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_762))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_906).xyz * _896) + min((_896 * ((_1085 * _1085) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_597, _650), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_896 * ((_1348 * _1348) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1147) * half(_1147)) / fast::max(_1133, 9.9999997473787516355514526367188e-05)) * half(_1166)) * half(_1166)), float3(65504.0))) * clamp(dot(_597, half3(_1138)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_896 * ((_1611 * _1611) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1410) * half(_1410)) / fast::max(_1396, 9.9999997473787516355514526367188e-05)) * half(_1429)) * half(_1429)), float3(65504.0))) * clamp(dot(_597, half3(_1401)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1620, half(1.0)));
    return out;
}

