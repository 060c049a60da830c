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
    half3 _622 = normalize(half3(in.v_normal));
    float3 _638 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _787 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _896 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _787)), half(0.0), half(1.0));
    half3 _904 = half3((half(0.1599999964237213134765625) * _896) * _896);
    half _913 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _787)), half(0.08900000154972076416015625), half(1.0));
    half3 _859 = reflect(-half3(_638), _622);
    float4 _920 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_622, half3(_638)), half(9.9999997473787516355514526367188e-05)), _913)), level(0.0));
    float4 _951 = facet_environment.sample(facet_environmentSmplr, float3(_859), level(_913 * (half(4.0) * (half(2.0) - _913))));
    half3 _874 = mix(half4(_920).xxx, half4(_920).yyy, _904) * (half3(float3(1.0)) + (_904 * ((half(1.0) / half4(_920).y) - half(1.0))));
    half3 _675 = half4(frame.lightDirection).xyz;
    half _1115 = clamp(dot(_859, _675), half(0.0), half(1.0));
    half _1118 = _1115 * _1115;
    half4 _1842 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1118 * _1118, _913), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1130 = _1842.x;
    float3 _1175 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1178 = dot(_1175, _1175);
    float3 _1183 = _1175 * rsqrt(fast::max(_1178, 9.9999999392252902907785028219223e-09));
    float _1187 = _1178 * float(frame.punctualLights[0].positionFalloff.w);
    float _1192 = fast::clamp(fma(-_1187, _1187, 1.0), 0.0, 1.0);
    float _1211 = fast::clamp(fma(dot(-_1183, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1378 = clamp(dot(_859, half3(_1183)), half(0.0), half(1.0));
    half _1381 = _1378 * _1378;
    half4 _1866 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1381 * _1381, _913), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1393 = _1866.x;
    float3 _1438 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1441 = dot(_1438, _1438);
    float3 _1446 = _1438 * rsqrt(fast::max(_1441, 9.9999999392252902907785028219223e-09));
    float _1450 = _1441 * float(frame.punctualLights[1].positionFalloff.w);
    float _1455 = fast::clamp(fma(-_1450, _1450, 1.0), 0.0, 1.0);
    float _1474 = fast::clamp(fma(dot(-_1446, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1641 = clamp(dot(_859, half3(_1446)), half(0.0), half(1.0));
    half _1644 = _1641 * _1641;
    half4 _1891 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1644 * _1644, _913), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1656 = _1891.x;
    half3 _1665 = ((fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_787))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_951).xyz * _874) + min((_874 * ((_1130 * _1130) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_622, _675), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_874 * ((_1393 * _1393) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1192) * half(_1192)) / fast::max(_1178, 9.9999997473787516355514526367188e-05)) * half(_1211)) * half(_1211)), float3(65504.0))) * clamp(dot(_622, half3(_1183)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_874 * ((_1656 * _1656) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1455) * half(_1455)) / fast::max(_1441, 9.9999997473787516355514526367188e-05)) * half(_1474)) * half(_1474)), float3(65504.0))) * clamp(dot(_622, half3(_1446)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1665, half(1.0)));
    return out;
}

