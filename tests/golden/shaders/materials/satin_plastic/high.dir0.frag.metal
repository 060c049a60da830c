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
    half3 _503 = normalize(half3(in.v_normal));
    float3 _507 = fast::normalize(in.v_toEye);
    half _616 = _503.y;
    half _621 = _503.z;
    half _626 = _503.x;
    half3 _694 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _616)) + (half4(frame.sh[2]).xyz * _621)) + (half4(frame.sh[3]).xyz * _626)) + (((((half4(frame.sh[4]).xyz * (_626 * _616)) + (half4(frame.sh[5]).xyz * (_616 * _621))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _621, _621, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_626 * _621))) + (half4(frame.sh[8]).xyz * fma(_626, _626, half(-float(_616 * _616))))), half3(float3(0.0)));
    half _744 = max(dot(_503, half3(_507)), half(9.9999997473787516355514526367188e-05));
    half3 _748 = reflect(-half3(_507), _503);
    float4 _783 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_744, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _809 = facet_environment.sample(facet_environmentSmplr, float3(_748), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _886 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    half3 _893 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1057 = half4(facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_744, _886)), level(0.0)));
    half _856 = _1057.z;
    float4 _914 = facet_environment.sample(facet_environmentSmplr, float3(_748), level(_886 * half(4.0)));
    out.fragColor = float4(half4(fma(half4(_914).xyz, _893 * _856, fma(half3(float3(params.facet_diffuseColor)), _694, half4(_809).xyz * (mix(half4(_783).xxx, half4(_783).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_783).y) - half(1.0)))))) * fma(half(-float(max(_893.x, max(_893.y, _893.z)))), _856, half(1.0))), half(1.0)));
    return out;
}

