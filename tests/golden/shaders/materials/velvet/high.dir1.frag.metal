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
    half3 _576 = normalize(half3(in.v_normal));
    float3 _580 = fast::normalize(in.v_toEye);
    half _700 = _576.y;
    half _705 = _576.z;
    half _710 = _576.x;
    half3 _778 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _700)) + (half4(frame.sh[2]).xyz * _705)) + (half4(frame.sh[3]).xyz * _710)) + (((((half4(frame.sh[4]).xyz * (_710 * _700)) + (half4(frame.sh[5]).xyz * (_700 * _705))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _705, _705, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_710 * _705))) + (half4(frame.sh[8]).xyz * fma(_710, _710, half(-float(_700 * _700))))), half3(float3(0.0)));
    half _819 = max(dot(_576, half3(_580)), half(9.9999997473787516355514526367188e-05));
    float4 _824 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_819, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _878 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1187 = half4(_824);
    half _837 = _1187.z;
    half _839 = fma(half(-float(max(_878.x, max(_878.y, _878.z)))), _837, half(1.0));
    float4 _899 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_580), _576)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _922 = dot(_576, half3(frame.lightDirection.xyz));
    half _924 = clamp(_922, half(0.0), half(1.0));
    half _936 = clamp(dot(_576, half3(fast::normalize(_580 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half _1007 = half(8192.0) * fma(half(-float(_924)), _819, _924 + _819);
    half _1011 = half(1.0) / (half(params.facet_alpha) * _1007);
    half3 _969 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_922 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_924), half3(float3(0.0)), half3(float3(1.0)))) * _839) + (_878 * ((((fma(_1011, _1007, half(2.0)) * pow(max(fma(half(-float(_936)), _936, half(1.0)), half(0.0)), half(0.5) * (_1011 * _1007))) * half(0.15915493667125701904296875)) * (_924 * (_1011 * (half(2048.0) * half(params.facet_alpha))))) * half4(_824).w))) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_899).xyz, _878 * _837, (half3(float3(params.facet_diffuseColor)) * _778) * _839) + _969, half(1.0)));
    return out;
}

