#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    half3 _457 = normalize(half3(in.v_normal));
    float3 _473 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _639 = max(dot(_457, half3(_473)), half(9.9999997473787516355514526367188e-05));
    float4 _644 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_639, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1344 = half4(_644);
    half _647 = _1344.w;
    float4 _672 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_473), _457)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _680 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half3 _510 = half4(frame.lightDirection).xyz;
    half _720 = clamp(dot(_457, _510), half(0.0), half(1.0));
    half _724 = clamp(dot(_457, normalize(half3(_473) + _510)), half(0.0), half(1.0));
    half _782 = half(2.0) + (half(1.0) / half(params.facet_alpha));
    half _785 = half(0.5) / half(params.facet_alpha);
    float3 _841 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _844 = dot(_841, _841);
    float3 _849 = _841 * rsqrt(fast::max(_844, 9.9999999392252902907785028219223e-09));
    float _853 = _844 * float(frame.punctualLights[0].positionFalloff.w);
    float _858 = fast::clamp(fma(-_853, _853, 1.0), 0.0, 1.0);
    float _877 = fast::clamp(fma(dot(-_849, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _924 = clamp(dot(_457, half3(_849)), half(0.0), half(1.0));
    half _928 = clamp(dot(_457, normalize(half3(_473) + half3(_849))), half(0.0), half(1.0));
    float3 _1045 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1048 = dot(_1045, _1045);
    float3 _1053 = _1045 * rsqrt(fast::max(_1048, 9.9999999392252902907785028219223e-09));
    float _1057 = _1048 * float(frame.punctualLights[1].positionFalloff.w);
    float _1062 = fast::clamp(fma(-_1057, _1057, 1.0), 0.0, 1.0);
    float _1081 = fast::clamp(fma(dot(-_1053, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1128 = clamp(dot(_457, half3(_1053)), half(0.0), half(1.0));
    half _1132 = clamp(dot(_457, normalize(half3(_473) + half3(_1053))), half(0.0), half(1.0));
    half3 _1213 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_672).xyz * (_680 * half4(_644).z)) + min((_680 * ((((_782 * pow(max(fma(half(-float(_724)), _724, half(1.0)), half(0.0)), _785)) * half(0.15915493667125701904296875)) * (_720 / (half(4.0) * fma(half(-float(_720)), _639, _720 + _639)))) * _647)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + min((_680 * ((((_782 * pow(max(fma(half(-float(_928)), _928, half(1.0)), half(0.0)), _785)) * half(0.15915493667125701904296875)) * (_924 / (half(4.0) * fma(half(-float(_924)), _639, _924 + _639)))) * _647)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_858) * half(_858)) / fast::max(_844, 9.9999997473787516355514526367188e-05)) * half(_877)) * half(_877)), float3(65504.0))), half3(float3(65504.0)))) + min((_680 * ((((_782 * pow(max(fma(half(-float(_1132)), _1132, half(1.0)), half(0.0)), _785)) * half(0.15915493667125701904296875)) * (_1128 / (half(4.0) * fma(half(-float(_1128)), _639, _1128 + _639)))) * _647)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1062) * half(_1062)) / fast::max(_1048, 9.9999997473787516355514526367188e-05)) * half(_1081)) * half(_1081)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1213, half(1.0)));
    return out;
}

