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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]])
{
    main0_out out = {};
    half3 _626 = normalize(half3(in.v_normal));
    float3 _642 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _753 = facet_irradiance.sample(facet_irradianceSmplr, float3(_626), level(0.0));
    half _802 = max(dot(_626, half3(_642)), half(9.9999997473787516355514526367188e-05));
    float4 _835 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_802, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _854 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_642), _626)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _899 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _902 = dot(_899, _899);
    float3 _907 = _899 * rsqrt(fast::max(_902, 9.9999999392252902907785028219223e-09));
    float _911 = _902 * float(frame.punctualLights[0].positionFalloff.w);
    float _916 = fast::clamp(fma(-_911, _911, 1.0), 0.0, 1.0);
    float _935 = fast::clamp(fma(dot(-_907, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1051 = fast::normalize(_642 + _907);
    half _998 = clamp(dot(_626, half3(_907)), half(0.0), half(1.0));
    half _1091 = half(4096.0) * half(params.facet_alpha);
    half4 _1116 = half4(cross(_626, half3(_1051)), half(params.facet_alpha) * clamp(dot(_626, half3(_1051)), half(0.0), half(1.0))) * half(64.0);
    half _1097 = _1091 / dot(_1116, _1116);
    half _1141 = half(1.0) - clamp(dot(half3(_907), half3(_1051)), half(0.0), half(1.0));
    half _1144 = _1141 * _1141;
    half3 _1152 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1026 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1202 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1205 = dot(_1202, _1202);
    float3 _1210 = _1202 * rsqrt(fast::max(_1205, 9.9999999392252902907785028219223e-09));
    float _1214 = _1205 * float(frame.punctualLights[1].positionFalloff.w);
    float _1219 = fast::clamp(fma(-_1214, _1214, 1.0), 0.0, 1.0);
    float _1238 = fast::clamp(fma(dot(-_1210, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1354 = fast::normalize(_642 + _1210);
    half _1301 = clamp(dot(_626, half3(_1210)), half(0.0), half(1.0));
    half4 _1419 = half4(cross(_626, half3(_1354)), half(params.facet_alpha) * clamp(dot(_626, half3(_1354)), half(0.0), half(1.0))) * half(64.0);
    half _1400 = _1091 / dot(_1419, _1419);
    half _1444 = half(1.0) - clamp(dot(half3(_1210), half3(_1354)), half(0.0), half(1.0));
    half _1447 = _1444 * _1444;
    half3 _1469 = (fma(half3(float3(params.facet_diffuseColor)), half4(_753).xyz, half4(_854).xyz * mix(half4(_835).xxx, half4(_835).yyy, half3(float3(params.facet_f0)))) + min((_1026 + ((half3(float3(params.facet_f0)) + (_1152 * ((_1144 * _1144) * _1141))) * min(min((_1097 * _1097) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _998) * _802, _998 + _802, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_916) * half(_916)) / fast::max(_902, 9.9999997473787516355514526367188e-05)) * half(_935)) * half(_935)), float3(65504.0))) * _998), half3(float3(65504.0)))) + min((_1026 + ((half3(float3(params.facet_f0)) + (_1152 * ((_1447 * _1447) * _1444))) * min(min((_1400 * _1400) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1301) * _802, _1301 + _802, half(params.facet_alpha)), half(65504.0)), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1219) * half(_1219)) / fast::max(_1205, 9.9999997473787516355514526367188e-05)) * half(_1238)) * half(_1238)), float3(65504.0))) * _1301), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1469, half(1.0)));
    return out;
}

