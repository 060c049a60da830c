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
    half _618 = max(dot(_457, half3(_473)), half(9.9999997473787516355514526367188e-05));
    float4 _623 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_618, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1199 = half4(_623);
    half _626 = _1199.w;
    float4 _651 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_473), _457)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _659 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    float3 _700 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _703 = dot(_700, _700);
    float3 _708 = _700 * rsqrt(fast::max(_703, 9.9999999392252902907785028219223e-09));
    float _712 = _703 * float(frame.punctualLights[0].positionFalloff.w);
    float _717 = fast::clamp(fma(-_712, _712, 1.0), 0.0, 1.0);
    float _736 = fast::clamp(fma(dot(-_708, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _783 = clamp(dot(_457, half3(_708)), half(0.0), half(1.0));
    half _787 = clamp(dot(_457, normalize(half3(_473) + half3(_708))), half(0.0), half(1.0));
    half _845 = half(2.0) + (half(1.0) / half(params.facet_alpha));
    half _848 = half(0.5) / half(params.facet_alpha);
    float3 _904 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _907 = dot(_904, _904);
    float3 _912 = _904 * rsqrt(fast::max(_907, 9.9999999392252902907785028219223e-09));
    float _916 = _907 * float(frame.punctualLights[1].positionFalloff.w);
    float _921 = fast::clamp(fma(-_916, _916, 1.0), 0.0, 1.0);
    float _940 = fast::clamp(fma(dot(-_912, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _987 = clamp(dot(_457, half3(_912)), half(0.0), half(1.0));
    half _991 = clamp(dot(_457, normalize(half3(_473) + half3(_912))), half(0.0), half(1.0));
    half3 _1072 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_651).xyz * (_659 * half4(_623).z)) + min((_659 * ((((_845 * pow(max(fma(half(-float(_787)), _787, half(1.0)), half(0.0)), _848)) * half(0.15915493667125701904296875)) * (_783 / (half(4.0) * fma(half(-float(_783)), _618, _783 + _618)))) * _626)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_717) * half(_717)) / fast::max(_703, 9.9999997473787516355514526367188e-05)) * half(_736)) * half(_736)), float3(65504.0))), half3(float3(65504.0)))) + min((_659 * ((((_845 * pow(max(fma(half(-float(_991)), _991, half(1.0)), half(0.0)), _848)) * half(0.15915493667125701904296875)) * (_987 / (half(4.0) * fma(half(-float(_987)), _618, _987 + _618)))) * _626)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_921) * half(_921)) / fast::max(_907, 9.9999997473787516355514526367188e-05)) * half(_940)) * half(_940)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1072, half(1.0)));
    return out;
}

