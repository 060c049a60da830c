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
    half3 _659 = normalize(half3(in.v_normal));
    float3 _663 = fast::normalize(in.v_toEye);
    half _817 = max(dot(_659, half3(_663)), half(9.9999997473787516355514526367188e-05));
    half3 _821 = reflect(-half3(_663), _659);
    float4 _856 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_817, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _875 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_856).y) - half(1.0)));
    float4 _887 = facet_environment.sample(facet_environmentSmplr, float3(_821), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _964 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _921 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_817, _964)), level(0.0));
    half3 _971 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1347 = half4(_921);
    half _934 = _1347.z;
    half _936 = fma(half(-float(max(_971.x, max(_971.y, _971.z)))), _934, half(1.0));
    half _980 = _964 * _964;
    float4 _997 = facet_environment.sample(facet_environmentSmplr, float3(_821), level(_964 * (half(4.0) * (half(2.0) - _964))));
    half3 _719 = half4(frame.lightDirection).xyz;
    half3 _731 = half4(frame.lightColor).xyz;
    half3 _1113 = normalize(half3(_663) + _719);
    half _1052 = clamp(dot(_659, _719), half(0.0), half(1.0));
    half _1056 = clamp(dot(_659, _1113), half(0.0), half(1.0));
    half3 _1140 = cross(_659, _1113);
    half _1143 = _1056 * half(params.facet_alpha);
    half _1157 = _1052 + _817;
    half _1160 = max(mix((half(2.0) * _1052) * _817, _1157, half(params.facet_alpha)), half(0.000244140625));
    half _1167 = (half(1024.0) * half(params.facet_alpha)) / (fma(_1143, _1143, dot(_1140, _1140)) * (half(6433.98193359375) * _1160));
    half _1204 = half(8192.0) * fma(half(-float(_1052)), _817, _1157);
    half _1208 = half(1.0) / (_980 * _1204);
    half3 _1237 = fma(half4(_997).xyz, _971 * _934, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_887).xyz * (mix(half4(_856).xxx, half4(_856).yyy, half3(float3(params.facet_f0))) * _875)) * _936) + min(fma((half3(float3(params.facet_f0)) * min(_1167 * (_1167 * (half(6.283185482025146484375) * _1160)), half(65504.0))) * _875, (_731 * _1052) * _936, (_971 * ((((fma(_1208, _1204, half(2.0)) * pow(max(fma(half(-float(_1056)), _1056, half(1.0)), half(0.0)), half(0.5) * (_1208 * _1204))) * half(0.15915493667125701904296875)) * (_1052 * (_1208 * (half(2048.0) * _980)))) * half4(_921).w)) * _731), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1237, half(1.0)));
    return out;
}

