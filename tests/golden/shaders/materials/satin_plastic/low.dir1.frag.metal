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
    half3 _640 = normalize(half3(in.v_normal));
    float3 _644 = fast::normalize(in.v_toEye);
    half _801 = max(dot(_640, half3(_644)), half(9.9999997473787516355514526367188e-05));
    half3 _805 = reflect(-half3(_644), _640);
    float4 _841 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_801, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _870 = facet_environment.sample(facet_environmentSmplr, float3(_805), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _820 = mix(half4(_841).xxx, half4(_841).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_841).y) - half(1.0))));
    half _947 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _904 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_801, _947)), level(0.0));
    half3 _954 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1308 = half4(_904);
    half _917 = _1308.z;
    half _919 = fma(half(-float(max(_954.x, max(_954.y, _954.z)))), _917, half(1.0));
    half _963 = _947 * _947;
    float4 _978 = facet_environment.sample(facet_environmentSmplr, float3(_805), level(_947 * (half(4.0) * (half(2.0) - _947))));
    half3 _700 = half4(frame.lightDirection).xyz;
    half3 _712 = half4(frame.lightColor).xyz;
    half _1033 = clamp(dot(_640, _700), half(0.0), half(1.0));
    half _1037 = clamp(dot(_640, normalize(half3(_644) + _700)), half(0.0), half(1.0));
    half _1116 = clamp(dot(_805, _700), half(0.0), half(1.0));
    half _1119 = _1116 * _1116;
    half4 _1331 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1119 * _1119, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1131 = _1331.x;
    half _1165 = half(8192.0) * fma(half(-float(_1033)), _801, _1033 + _801);
    half _1169 = half(1.0) / (_963 * _1165);
    half3 _1198 = fma(half4(_978).xyz, _954 * _917, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_870).xyz * _820) * _919) + min(fma(_820 * ((_1131 * _1131) * half(5.092957973480224609375)), (_712 * _1033) * _919, (_954 * ((((fma(_1169, _1165, half(2.0)) * pow(max(fma(half(-float(_1037)), _1037, half(1.0)), half(0.0)), half(0.5) * (_1169 * _1165))) * half(0.15915493667125701904296875)) * (_1033 * (_1169 * (half(2048.0) * _963)))) * half4(_904).w)) * _712), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1198, half(1.0)));
    return out;
}

