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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _588 = normalize(half3(in.v_normal));
    float3 _604 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _771 = max(dot(_588, half3(_604)), half(9.9999997473787516355514526367188e-05));
    float4 _804 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_771, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _823 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_604), _588)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _928 = fast::normalize(_604 + frame.lightDirection.xyz);
    half _881 = clamp(dot(_588, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _968 = half(4096.0) * half(params.facet_alpha);
    half4 _993 = half4(cross(_588, half3(_928)), half(params.facet_alpha) * clamp(dot(_588, half3(_928)), half(0.0), half(1.0))) * half(64.0);
    half _974 = _968 / dot(_993, _993);
    half _1018 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_928)), half(0.0), half(1.0));
    half _1021 = _1018 * _1018;
    half3 _1029 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1073 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1076 = dot(_1073, _1073);
    float3 _1081 = _1073 * rsqrt(fast::max(_1076, 9.9999999392252902907785028219223e-09));
    float _1085 = _1076 * float(frame.punctualLights[0].positionFalloff.w);
    float _1090 = fast::clamp(fma(-_1085, _1085, 1.0), 0.0, 1.0);
    float _1109 = fast::clamp(fma(dot(-_1081, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1217 = fast::normalize(_604 + _1081);
    half _1170 = clamp(dot(_588, half3(_1081)), half(0.0), half(1.0));
    half4 _1282 = half4(cross(_588, half3(_1217)), half(params.facet_alpha) * clamp(dot(_588, half3(_1217)), half(0.0), half(1.0))) * half(64.0);
    half _1263 = _968 / dot(_1282, _1282);
    half _1307 = half(1.0) - clamp(dot(half3(_1081), half3(_1217)), half(0.0), half(1.0));
    half _1310 = _1307 * _1307;
    float3 _1362 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1365 = dot(_1362, _1362);
    float3 _1370 = _1362 * rsqrt(fast::max(_1365, 9.9999999392252902907785028219223e-09));
    float _1374 = _1365 * float(frame.punctualLights[1].positionFalloff.w);
    float _1379 = fast::clamp(fma(-_1374, _1374, 1.0), 0.0, 1.0);
    float _1398 = fast::clamp(fma(dot(-_1370, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1506 = fast::normalize(_604 + _1370);
    half _1459 = clamp(dot(_588, half3(_1370)), half(0.0), half(1.0));
    half4 _1571 = half4(cross(_588, half3(_1506)), half(params.facet_alpha) * clamp(dot(_588, half3(_1506)), half(0.0), half(1.0))) * half(64.0);
    half _1552 = _968 / dot(_1571, _1571);
    half _1596 = half(1.0) - clamp(dot(half3(_1370), half3(_1506)), half(0.0), half(1.0));
    half _1599 = _1596 * _1596;
    half3 _1615 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_823).xyz * mix(half4(_804).xxx, half4(_804).yyy, half3(float3(params.facet_f0)))) + min(((half3(float3(params.facet_f0)) + (_1029 * ((_1021 * _1021) * _1018))) * min(min((_974 * _974) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _881) * _771, _881 + _771, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * (half4(frame.lightColor).xyz * _881), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) + (_1029 * ((_1310 * _1310) * _1307))) * min(min((_1263 * _1263) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1170) * _771, _1170 + _771, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1090) * half(_1090)) / fast::max(_1076, 9.9999997473787516355514526367188e-05)) * half(_1109)) * half(_1109)), float3(65504.0))) * _1170), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) + (_1029 * ((_1599 * _1599) * _1596))) * min(min((_1552 * _1552) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1459) * _771, _1459 + _771, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1379) * half(_1379)) / fast::max(_1365, 9.9999997473787516355514526367188e-05)) * half(_1398)) * half(_1398)), float3(65504.0))) * _1459), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1615, half(1.0)));
    return out;
}

