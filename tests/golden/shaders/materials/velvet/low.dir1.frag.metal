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
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _503 = normalize(half3(in.v_normal));
    float3 _507 = fast::normalize(in.v_toEye);
    half _682 = max(dot(_503, half3(_507)), half(9.9999997473787516355514526367188e-05));
    float4 _687 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_682, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _741 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1017 = half4(_687);
    half _700 = _1017.z;
    half _702 = fma(half(-float(max(_741.x, max(_741.y, _741.z)))), _700, half(1.0));
    float4 _760 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_507), _503)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _539 = half4(frame.lightDirection).xyz;
    half _783 = dot(_503, _539);
    half _785 = clamp(_783, half(0.0), half(1.0));
    half _797 = clamp(dot(_503, normalize(half3(_507) + _539)), half(0.0), half(1.0));
    half _866 = half(8192.0) * fma(half(-float(_785)), _682, _785 + _682);
    half _870 = half(1.0) / (half(params.facet_alpha) * _866);
    half3 _830 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_783 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_785), half3(float3(0.0)), half3(float3(1.0)))) * _702) + (_741 * ((((fma(_870, _866, half(2.0)) * pow(max(fma(half(-float(_797)), _797, half(1.0)), half(0.0)), half(0.5) * (_870 * _866))) * half(0.15915493667125701904296875)) * (_785 * (_870 * (half(2048.0) * half(params.facet_alpha))))) * half4(_687).w))) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_760).xyz, _741 * _700, (half3(float3(params.facet_diffuseColor)) * max(((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _503.y)) + (half4(frame.sh[2]).xyz * _503.z)) + (half4(frame.sh[3]).xyz * _503.x), half3(float3(0.0)))) * _702) + _830, half(1.0)));
    return out;
}

