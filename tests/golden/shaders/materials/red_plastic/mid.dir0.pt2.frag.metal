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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    half3 _536 = normalize(half3(in.v_normal));
    float3 _552 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _734 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_536, half3(_552)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _713 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_552), _536)), level(params.facet_environmentLod));
    float3 _787 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _790 = dot(_787, _787);
    float3 _795 = _787 * rsqrt(fast::max(_790, 9.9999999392252902907785028219223e-09));
    float _799 = _790 * float(frame.punctualLights[0].positionFalloff.w);
    float _804 = fast::clamp(fma(-_799, _799, 1.0), 0.0, 1.0);
    float _823 = fast::clamp(fma(dot(-_795, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _887 = half3(_552) + half3(_795);
    half3 _897 = _887 * (half(64.0) * rsqrt(dot(_887, _887)));
    half _906 = clamp(dot(half3(_795), _897) * half(0.015625), half(0.0), half(1.0));
    half _1024 = max(_906 * _906, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1053 = half4(cross(_536, _897), half(params.facet_alpha) * clamp(dot(_536, _897), half(0.0), half(64.0)));
    half _1034 = half(params.facet_ggxAlphaScaled) / (dot(_1053, _1053) * _1024);
    float3 _1097 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1100 = dot(_1097, _1097);
    float3 _1105 = _1097 * rsqrt(fast::max(_1100, 9.9999999392252902907785028219223e-09));
    float _1109 = _1100 * float(frame.punctualLights[1].positionFalloff.w);
    float _1114 = fast::clamp(fma(-_1109, _1109, 1.0), 0.0, 1.0);
    float _1133 = fast::clamp(fma(dot(-_1105, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1197 = half3(_552) + half3(_1105);
    half3 _1207 = _1197 * (half(64.0) * rsqrt(dot(_1197, _1197)));
    half _1216 = clamp(dot(half3(_1105), _1207) * half(0.015625), half(0.0), half(1.0));
    half _1334 = max(_1216 * _1216, half(0.1500000059604644775390625)) * half(params.facet_ziomaRoughnessFactor);
    half4 _1363 = half4(cross(_536, _1207), half(params.facet_alpha) * clamp(dot(_536, _1207), half(0.0), half(64.0)));
    half _1344 = half(params.facet_ggxAlphaScaled) / (dot(_1363, _1363) * _1334);
    half3 _1371 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_713).xyz * mix(half4(_734).xxx, half4(_734).yyy, half3(float3(params.facet_f0)))) + min((half3(float3(params.facet_f0)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_804) * half(_804)) / fast::max(_790, 9.9999997473787516355514526367188e-05)) * half(_823)) * half(_823)), float3(65504.0)))) * (min((_1034 * _1034) * _1024, half(65504.0)) * clamp(dot(_536, half3(_795)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((half3(float3(params.facet_f0)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1114) * half(_1114)) / fast::max(_1100, 9.9999997473787516355514526367188e-05)) * half(_1133)) * half(_1133)), float3(65504.0)))) * (min((_1344 * _1344) * _1334, half(65504.0)) * clamp(dot(_536, half3(_1105)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1371, half(1.0)));
    return out;
}

