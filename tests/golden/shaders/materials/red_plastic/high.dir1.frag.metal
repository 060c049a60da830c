#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
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
    half3 _659 = normalize(half3(in.v_normal));
    float3 _663 = fast::normalize(in.v_toEye);
    half _784 = _659.y;
    half _789 = _659.z;
    half _794 = _659.x;
    half3 _862 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _784)) + (half4(frame.sh[2]).xyz * _789)) + (half4(frame.sh[3]).xyz * _794)) + (((((half4(frame.sh[4]).xyz * (_794 * _784)) + (half4(frame.sh[5]).xyz * (_784 * _789))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _789, _789, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_794 * _789))) + (half4(frame.sh[8]).xyz * fma(_794, _794, half(-float(_784 * _784))))), half3(float3(0.0)));
    half _912 = max(dot(_659, half3(_663)), half(9.9999997473787516355514526367188e-05));
    float4 _951 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_912, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _970 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_951).y) - half(1.0)));
    float4 _977 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_663), _659)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1093 = fast::normalize(_663 + frame.lightDirection.xyz);
    half _1037 = clamp(dot(_659, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1133 = cross(_659, half3(_1093));
    half _1136 = clamp(dot(_659, half3(_1093)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1145 = half(params.facet_alpha) / fma(_1136, _1136, dot(_1133, _1133));
    half _1159 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1165 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1193 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1093)), half(0.0), half(1.0));
    half _1196 = _1193 * _1193;
    half3 _1218 = fma(half3(float3(params.facet_diffuseColor)), _862, half4(_977).xyz * (mix(half4(_951).xxx, half4(_951).yyy, half3(float3(params.facet_f0))) * _970)) + min(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1196 * _1196) * _1193))) * min(min((_1145 * _1145) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1037, sqrt(fma(_912 * _912, _1165, _1159)), _912 * sqrt(fma(_1037 * _1037, _1165, _1159))), half(65504.0)), half(65504.0)), _970, half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1037), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1218, half(1.0)));
    return out;
}

