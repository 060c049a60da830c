#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _538 = normalize(half3(in.v_normal));
    float3 _542 = fast::normalize(in.v_toEye);
    half _708 = max(dot(_538, half3(_542)), half(9.9999997473787516355514526367188e-05));
    half3 _712 = reflect(-half3(_542), _538);
    float4 _748 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_708, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _777 = facet_environment.sample(facet_environmentSmplr, float3(_712), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _727 = mix(half4(_748).xxx, half4(_748).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_748).y) - half(1.0))));
    half3 _590 = half4(frame.lightDirection).xyz;
    half _906 = clamp(dot(_712, _590), half(0.0), half(1.0));
    half _909 = _906 * _906;
    half4 _1131 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_909 * _909, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _921 = _1131.x;
    half _968 = clamp(half(params.coat), half(0.0), half(1.0));
    half _974 = half(1.0) - _708;
    half _977 = _974 * _974;
    half _993 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1003 = facet_environment.sample(facet_environmentSmplr, float3(_712), level(_993 * (half(4.0) * (half(2.0) - _993))));
    half3 _963 = mix(fma(half4(_777).xyz, _727, min((_727 * ((_921 * _921) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_538, _590), half(0.0), half(1.0))), half3(float3(65504.0)))), half4(_1003).xyz, half3(fma(half(0.039999999105930328369140625), _968, (half(0.959999978542327880859375) * _968) * ((_977 * _977) * _974))));
    out.fragColor = float4(half4(_963, half(1.0)));
    return out;
}

