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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _509 = normalize(half3(in.v_normal));
    float3 _513 = fast::normalize(in.v_toEye);
    half _622 = _509.y;
    half _627 = _509.z;
    half _632 = _509.x;
    half3 _700 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _622)) + (half4(frame.sh[2]).xyz * _627)) + (half4(frame.sh[3]).xyz * _632)) + (((((half4(frame.sh[4]).xyz * (_632 * _622)) + (half4(frame.sh[5]).xyz * (_622 * _627))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _627, _627, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_632 * _627))) + (half4(frame.sh[8]).xyz * fma(_632, _632, half(-float(_622 * _622))))), half3(float3(0.0)));
    half _750 = max(dot(_509, half3(_513)), half(9.9999997473787516355514526367188e-05));
    half3 _754 = reflect(-half3(_513), _509);
    float4 _789 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_750, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _820 = facet_environment.sample(facet_environmentSmplr, float3(_754), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _897 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    half3 _904 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1075 = half4(facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_750, _897)), level(0.0)));
    half _867 = _1075.z;
    float4 _930 = facet_environment.sample(facet_environmentSmplr, float3(_754), level(_897 * (half(4.0) * (half(2.0) - _897))));
    out.fragColor = float4(half4(fma(half4(_930).xyz, _904 * _867, fma(half3(float3(params.facet_diffuseColor)), _700, half4(_820).xyz * (mix(half4(_789).xxx, half4(_789).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_789).y) - half(1.0)))))) * fma(half(-float(max(_904.x, max(_904.y, _904.z)))), _867, half(1.0))), half(1.0)));
    return out;
}

