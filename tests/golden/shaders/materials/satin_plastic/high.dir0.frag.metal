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
    half3 _485 = normalize(half3(in.v_normal));
    float3 _489 = fast::normalize(in.v_toEye);
    half _598 = _485.y;
    half _603 = _485.z;
    half _608 = _485.x;
    half3 _676 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _598)) + (half4(frame.sh[2]).xyz * _603)) + (half4(frame.sh[3]).xyz * _608)) + (((((half4(frame.sh[4]).xyz * (_608 * _598)) + (half4(frame.sh[5]).xyz * (_598 * _603))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _603, _603, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_608 * _603))) + (half4(frame.sh[8]).xyz * fma(_608, _608, half(-float(_598 * _598))))), half3(float3(0.0)));
    half _726 = max(dot(_485, half3(_489)), half(9.9999997473787516355514526367188e-05));
    half3 _730 = reflect(-half3(_489), _485);
    float4 _765 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_726, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _791 = facet_environment.sample(facet_environmentSmplr, float3(_730), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _864 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    half3 _871 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1021 = half4(facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_726, _864)), level(0.0)));
    half _837 = _1021.z;
    float4 _878 = facet_environment.sample(facet_environmentSmplr, float3(_730), level(_864 * half(4.0)));
    out.fragColor = float4(half4(fma(half4(_878).xyz, _871 * _837, fma(half3(float3(params.facet_diffuseColor)), _676, half4(_791).xyz * (mix(half4(_765).xxx, half4(_765).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_765).y) - half(1.0)))))) * fma(half(-float(max(_871.x, max(_871.y, _871.z)))), _837, half(1.0))), half(1.0)));
    return out;
}

