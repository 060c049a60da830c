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
    char _m8_pad[12];
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
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
    half3 _555 = normalize(half3(in.v_normal));
    float3 _559 = fast::normalize(in.v_toEye);
    half _679 = _555.y;
    half _684 = _555.z;
    half _689 = _555.x;
    half3 _757 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _679)) + (half4(frame.sh[2]).xyz * _684)) + (half4(frame.sh[3]).xyz * _689)) + (((((half4(frame.sh[4]).xyz * (_689 * _679)) + (half4(frame.sh[5]).xyz * (_679 * _684))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _684, _684, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_689 * _684))) + (half4(frame.sh[8]).xyz * fma(_689, _689, half(-float(_679 * _679))))), half3(float3(0.0)));
    half _796 = max(dot(_555, half3(_559)), half(9.9999997473787516355514526367188e-05));
    float4 _801 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_796, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1149 = half4(_801);
    half _814 = _1149.z;
    half _816 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _814, half(1.0));
    float4 _830 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_559), _555)), level(params.facet_sheenLod));
    half _886 = dot(_555, half3(frame.lightDirection.xyz));
    half _888 = clamp(_886, half(0.0), half(1.0));
    half _900 = clamp(dot(_555, half3(fast::normalize(_559 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half _971 = half(8192.0) * fma(half(-float(_888)), _796, _888 + _796);
    half _975 = half(1.0) / (half(params.facet_alpha) * _971);
    half3 _933 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_886 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_888), half3(float3(0.0)), half3(float3(1.0)))) * _816) + (half3(float3(params.facet_sheenColor)) * ((((fma(_975, _971, half(2.0)) * pow(max(fma(half(-float(_900)), _900, half(1.0)), half(0.0)), half(0.5) * (_975 * _971))) * half(0.15915493667125701904296875)) * (_888 * (_975 * (half(2048.0) * half(params.facet_alpha))))) * half4(_801).w))) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_830).xyz, half3(float3(params.facet_sheenColor)) * _814, (half3(float3(params.facet_diffuseColor)) * _757) * _816) + _933, half(1.0)));
    return out;
}

