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
    half3 _471 = normalize(half3(in.v_normal));
    float3 _487 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _629 = max(dot(_471, half3(_487)), half(9.9999997473787516355514526367188e-05));
    float4 _634 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_629, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _680 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1231 = half4(_634);
    half _647 = _1231.z;
    half4 _1235 = half4(_634);
    half _651 = _1235.w;
    float4 _687 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_487), _471)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _724 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _727 = dot(_724, _724);
    float3 _732 = _724 * rsqrt(fast::max(_727, 9.9999999392252902907785028219223e-09));
    float _736 = _727 * float(frame.punctualLights[0].positionFalloff.w);
    float _741 = fast::clamp(fma(-_736, _736, 1.0), 0.0, 1.0);
    float _760 = fast::clamp(fma(dot(-_732, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _797 = clamp(dot(_471, half3(_732)), half(0.0), half(1.0));
    half _811 = clamp(dot(_471, normalize(half3(_487) + half3(_732))), half(0.0), half(1.0));
    half _858 = half(8192.0) * fma(half(-float(_797)), _629, _797 + _629);
    half _862 = half(1.0) / (half(params.facet_alpha) * _858);
    half _869 = half(2048.0) * half(params.facet_alpha);
    float3 _927 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _930 = dot(_927, _927);
    float3 _935 = _927 * rsqrt(fast::max(_930, 9.9999999392252902907785028219223e-09));
    float _939 = _930 * float(frame.punctualLights[1].positionFalloff.w);
    float _944 = fast::clamp(fma(-_939, _939, 1.0), 0.0, 1.0);
    float _963 = fast::clamp(fma(dot(-_935, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1000 = clamp(dot(_471, half3(_935)), half(0.0), half(1.0));
    half _1014 = clamp(dot(_471, normalize(half3(_487) + half3(_935))), half(0.0), half(1.0));
    half _1061 = half(8192.0) * fma(half(-float(_1000)), _629, _1000 + _629);
    half _1065 = half(1.0) / (half(params.facet_alpha) * _1061);
    half3 _1094 = (fma(half4(_687).xyz, _680 * _647, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_680.x, max(_680.y, _680.z)))), _647, half(1.0))) + min((_680 * ((((fma(_862, _858, half(2.0)) * pow(max(fma(half(-float(_811)), _811, half(1.0)), half(0.0)), half(0.5) * (_862 * _858))) * half(0.15915493667125701904296875)) * (_797 * (_862 * _869))) * _651)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_741) * half(_741)) / fast::max(_727, 9.9999997473787516355514526367188e-05)) * half(_760)) * half(_760)), float3(65504.0))), half3(float3(65504.0)))) + min((_680 * ((((fma(_1065, _1061, half(2.0)) * pow(max(fma(half(-float(_1014)), _1014, half(1.0)), half(0.0)), half(0.5) * (_1065 * _1061))) * half(0.15915493667125701904296875)) * (_1000 * (_1065 * _869))) * _651)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_944) * half(_944)) / fast::max(_930, 9.9999997473787516355514526367188e-05)) * half(_963)) * half(_963)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1094, half(1.0)));
    return out;
}

