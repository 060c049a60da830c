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
    half _750 = max(dot(_588, half3(_604)), half(9.9999997473787516355514526367188e-05));
    float4 _783 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_750, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _802 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_604), _588)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _847 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _850 = dot(_847, _847);
    float3 _855 = _847 * rsqrt(fast::max(_850, 9.9999999392252902907785028219223e-09));
    float _859 = _850 * float(frame.punctualLights[0].positionFalloff.w);
    float _864 = fast::clamp(fma(-_859, _859, 1.0), 0.0, 1.0);
    float _883 = fast::clamp(fma(dot(-_855, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _991 = fast::normalize(_604 + _855);
    half _944 = clamp(dot(_588, half3(_855)), half(0.0), half(1.0));
    half _1031 = half(4096.0) * half(params.facet_alpha);
    half4 _1056 = half4(cross(_588, half3(_991)), half(params.facet_alpha) * clamp(dot(_588, half3(_991)), half(0.0), half(1.0))) * half(64.0);
    half _1037 = _1031 / dot(_1056, _1056);
    half _1081 = half(1.0) - clamp(dot(half3(_855), half3(_991)), half(0.0), half(1.0));
    half _1084 = _1081 * _1081;
    half3 _1092 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1136 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1139 = dot(_1136, _1136);
    float3 _1144 = _1136 * rsqrt(fast::max(_1139, 9.9999999392252902907785028219223e-09));
    float _1148 = _1139 * float(frame.punctualLights[1].positionFalloff.w);
    float _1153 = fast::clamp(fma(-_1148, _1148, 1.0), 0.0, 1.0);
    float _1172 = fast::clamp(fma(dot(-_1144, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1280 = fast::normalize(_604 + _1144);
    half _1233 = clamp(dot(_588, half3(_1144)), half(0.0), half(1.0));
    half4 _1345 = half4(cross(_588, half3(_1280)), half(params.facet_alpha) * clamp(dot(_588, half3(_1280)), half(0.0), half(1.0))) * half(64.0);
    half _1326 = _1031 / dot(_1345, _1345);
    half _1370 = half(1.0) - clamp(dot(half3(_1144), half3(_1280)), half(0.0), half(1.0));
    half _1373 = _1370 * _1370;
    half3 _1389 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_802).xyz * mix(half4(_783).xxx, half4(_783).yyy, half3(float3(params.facet_f0)))) + min(((half3(float3(params.facet_f0)) + (_1092 * ((_1084 * _1084) * _1081))) * min(min((_1037 * _1037) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _944) * _750, _944 + _750, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_864) * half(_864)) / fast::max(_850, 9.9999997473787516355514526367188e-05)) * half(_883)) * half(_883)), float3(65504.0))) * _944), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) + (_1092 * ((_1373 * _1373) * _1370))) * min(min((_1326 * _1326) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1233) * _750, _1233 + _750, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1153) * half(_1153)) / fast::max(_1139, 9.9999997473787516355514526367188e-05)) * half(_1172)) * half(_1172)), float3(65504.0))) * _1233), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1389, half(1.0)));
    return out;
}

