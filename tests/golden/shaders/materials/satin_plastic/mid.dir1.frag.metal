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
    half3 _674 = normalize(half3(in.v_normal));
    float3 _678 = fast::normalize(in.v_toEye);
    half _832 = max(dot(_674, half3(_678)), half(9.9999997473787516355514526367188e-05));
    half3 _836 = reflect(-half3(_678), _674);
    float4 _871 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_832, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _890 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_871).y) - half(1.0)));
    float4 _897 = facet_environment.sample(facet_environmentSmplr, float3(_836), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _974 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _931 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_832, _974)), level(0.0));
    half3 _981 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1363 = half4(_931);
    half _944 = _1363.z;
    half _946 = fma(half(-float(max(_981.x, max(_981.y, _981.z)))), _944, half(1.0));
    half _990 = _974 * _974;
    float4 _1002 = facet_environment.sample(facet_environmentSmplr, float3(_836), level(_974 * half(4.0)));
    half3 _734 = half4(frame.lightDirection).xyz;
    half3 _746 = half4(frame.lightColor).xyz;
    half3 _1118 = normalize(half3(_678) + _734);
    half _1057 = clamp(dot(_674, _734), half(0.0), half(1.0));
    half _1061 = clamp(dot(_674, _1118), half(0.0), half(1.0));
    half3 _1181 = cross(_674, _1118) * half(64.0);
    half _1185 = _1061 * (half(64.0) * half(params.facet_alpha));
    half _1156 = _1057 + _832;
    half _1164 = half(6.283185482025146484375) * max(mix((half(2.0) * _1057) * _832, _1156, half(params.facet_alpha)), half(0.000244140625));
    half _1166 = (half(4096.0) * half(params.facet_alpha)) / (fma(_1185, _1185, dot(_1181, _1181)) * _1164);
    half _1222 = half(8192.0) * fma(half(-float(_1057)), _832, _1156);
    half _1226 = half(1.0) / (_990 * _1222);
    half3 _1255 = fma(half4(_1002).xyz, _981 * _944, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_897).xyz * (mix(half4(_871).xxx, half4(_871).yyy, half3(float3(params.facet_f0))) * _890)) * _946) + min(fma((half3(float3(params.facet_f0)) * min(_1166 * (_1166 * _1164), half(65504.0))) * _890, (_746 * _1057) * _946, (_981 * ((((fma(_1226, _1222, half(2.0)) * pow(max(fma(half(-float(_1061)), _1061, half(1.0)), half(0.0)), half(0.5) * (_1226 * _1222))) * half(0.15915493667125701904296875)) * (_1057 * (_1226 * (half(2048.0) * _990)))) * half4(_931).w)) * _746), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1255, half(1.0)));
    return out;
}

