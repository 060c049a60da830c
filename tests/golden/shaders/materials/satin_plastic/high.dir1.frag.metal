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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _689 = normalize(half3(in.v_normal));
    float3 _693 = fast::normalize(in.v_toEye);
    half _845 = max(dot(_689, half3(_693)), half(9.9999997473787516355514526367188e-05));
    half3 _849 = reflect(-half3(_693), _689);
    float4 _878 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_845, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _897 = facet_environment.sample(facet_environmentSmplr, float3(_849), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _974 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _931 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_845, _974)), level(0.0));
    half3 _981 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1389 = half4(_931);
    half _944 = _1389.z;
    half _946 = fma(half(-float(max(_981.x, max(_981.y, _981.z)))), _944, half(1.0));
    half _990 = _974 * _974;
    float4 _1005 = facet_environment.sample(facet_environmentSmplr, float3(_849), level(_974 * (half(4.0) * (half(2.0) - _974))));
    half3 _761 = half4(frame.lightColor).xyz;
    float3 _1119 = fast::normalize(_693 + frame.lightDirection.xyz);
    half _1060 = clamp(dot(_689, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1064 = clamp(dot(_689, half3(_1119)), half(0.0), half(1.0));
    half4 _1184 = half4(cross(_689, half3(_1119)), half(params.facet_alpha) * _1064) * half(64.0);
    half _1165 = (half(4096.0) * half(params.facet_alpha)) / dot(_1184, _1184);
    half _1197 = _1060 + _845;
    half _1209 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1119)), half(0.0), half(1.0));
    half _1212 = _1209 * _1209;
    half _1253 = half(8192.0) * fma(half(-float(_1060)), _845, _1197);
    half _1257 = half(1.0) / (_990 * _1253);
    half3 _1100 = min(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1212 * _1212) * _1209))) * min(min((_1165 * _1165) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1060) * _845, _1197, half(params.facet_alpha)), half(65504.0)), half(65504.0)), (_761 * _1060) * _946, (_981 * ((((fma(_1257, _1253, half(2.0)) * pow(max(fma(half(-float(_1064)), _1064, half(1.0)), half(0.0)), half(0.5) * (_1257 * _1253))) * half(0.15915493667125701904296875)) * (_1060 * (_1257 * (half(2048.0) * _990)))) * half4(_931).w)) * _761), half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_1005).xyz, _981 * _944, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_897).xyz * mix(half4(_878).xxx, half4(_878).yyy, half3(float3(params.facet_f0)))) * _946) + _1100, half(1.0)));
    return out;
}

