#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
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
    float3 v_toEye [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _617 = normalize(half3(in.v_normal));
    float3 _621 = fast::normalize(in.v_toEye);
    half _776 = max(dot(_617, half3(_621)), half(9.9999997473787516355514526367188e-05));
    half3 _780 = reflect(-half3(_621), _617);
    float4 _810 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_776, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _819 = mix(half4(_810).xxx, half4(_810).yyy, half3(float3(params.facet_f0)));
    float4 _829 = facet_environment.sample(facet_environmentSmplr, float3(_780), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _906 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _863 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_776, _906)), level(0.0));
    half3 _913 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1261 = half4(_863);
    half _876 = _1261.z;
    half _878 = fma(half(-float(max(_913.x, max(_913.y, _913.z)))), _876, half(1.0));
    half _922 = _906 * _906;
    float4 _937 = facet_environment.sample(facet_environmentSmplr, float3(_780), level(_906 * (half(4.0) * (half(2.0) - _906))));
    half3 _677 = half4(frame.lightDirection).xyz;
    half3 _689 = half4(frame.lightColor).xyz;
    half _992 = clamp(dot(_617, _677), half(0.0), half(1.0));
    half _996 = clamp(dot(_617, normalize(half3(_621) + _677)), half(0.0), half(1.0));
    half _1075 = clamp(dot(_780, _677), half(0.0), half(1.0));
    half _1078 = _1075 * _1075;
    half4 _1284 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1078 * _1078, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1090 = _1284.x;
    half _1124 = half(8192.0) * fma(half(-float(_992)), _776, _992 + _776);
    half _1128 = half(1.0) / (_922 * _1124);
    half3 _1157 = fma(half4(_937).xyz, _913 * _876, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_829).xyz * _819) * _878) + min(fma(_819 * ((_1090 * _1090) * half(5.092957973480224609375)), (_689 * _992) * _878, (_913 * ((((fma(_1128, _1124, half(2.0)) * pow(max(fma(half(-float(_996)), _996, half(1.0)), half(0.0)), half(0.5) * (_1128 * _1124))) * half(0.15915493667125701904296875)) * (_992 * (_1128 * (half(2048.0) * _922)))) * half4(_863).w)) * _689), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1157, half(1.0)));
    return out;
}

