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
    half3 _673 = normalize(half3(in.v_normal));
    float3 _677 = fast::normalize(in.v_toEye);
    half _831 = max(dot(_673, half3(_677)), half(9.9999997473787516355514526367188e-05));
    half3 _835 = reflect(-half3(_677), _673);
    float4 _870 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_831, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _889 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_870).y) - half(1.0)));
    float4 _896 = facet_environment.sample(facet_environmentSmplr, float3(_835), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _973 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _930 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_831, _973)), level(0.0));
    half3 _980 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1359 = half4(_930);
    half _943 = _1359.z;
    half _945 = fma(half(-float(max(_980.x, max(_980.y, _980.z)))), _943, half(1.0));
    half _989 = _973 * _973;
    float4 _1001 = facet_environment.sample(facet_environmentSmplr, float3(_835), level(_973 * half(4.0)));
    half3 _733 = half4(frame.lightDirection).xyz;
    half3 _745 = half4(frame.lightColor).xyz;
    half3 _1117 = normalize(half3(_677) + _733);
    half _1056 = clamp(dot(_673, _733), half(0.0), half(1.0));
    half _1060 = clamp(dot(_673, _1117), half(0.0), half(1.0));
    half4 _1186 = half4(cross(_673, _1117), half(params.facet_alpha) * _1060) * half(64.0);
    half _1155 = _1056 + _831;
    half _1163 = half(6.283185482025146484375) * max(mix((half(2.0) * _1056) * _831, _1155, half(params.facet_alpha)), half(0.000244140625));
    half _1165 = (half(4096.0) * half(params.facet_alpha)) / (dot(_1186, _1186) * _1163);
    half _1219 = half(8192.0) * fma(half(-float(_1056)), _831, _1155);
    half _1223 = half(1.0) / (_989 * _1219);
    half3 _1252 = fma(half4(_1001).xyz, _980 * _943, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_896).xyz * (mix(half4(_870).xxx, half4(_870).yyy, half3(float3(params.facet_f0))) * _889)) * _945) + min(fma((half3(float3(params.facet_f0)) * min(_1165 * (_1165 * _1163), half(65504.0))) * _889, (_745 * _1056) * _945, (_980 * ((((fma(_1223, _1219, half(2.0)) * pow(max(fma(half(-float(_1060)), _1060, half(1.0)), half(0.0)), half(0.5) * (_1223 * _1219))) * half(0.15915493667125701904296875)) * (_1056 * (_1223 * (half(2048.0) * _989)))) * half4(_930).w)) * _745), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1252, half(1.0)));
    return out;
}

