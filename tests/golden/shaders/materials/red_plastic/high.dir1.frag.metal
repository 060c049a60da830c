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
    half3 _678 = normalize(half3(in.v_normal));
    float3 _682 = fast::normalize(in.v_toEye);
    half _800 = _678.y;
    half _805 = _678.z;
    half _810 = _678.x;
    half3 _878 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _800)) + (half4(frame.sh[2]).xyz * _805)) + (half4(frame.sh[3]).xyz * _810)) + (((((half4(frame.sh[4]).xyz * (_810 * _800)) + (half4(frame.sh[5]).xyz * (_800 * _805))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _805, _805, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_810 * _805))) + (half4(frame.sh[8]).xyz * fma(_810, _810, half(-float(_800 * _800))))), half3(float3(0.0)));
    half _928 = max(dot(_678, half3(_682)), half(9.9999997473787516355514526367188e-05));
    float4 _967 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_928, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _986 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_967).y) - half(1.0)));
    float4 _993 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_682), _678)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1109 = fast::normalize(_682 + frame.lightDirection.xyz);
    half _1053 = clamp(dot(_678, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half4 _1174 = half4(cross(_678, half3(_1109)), half(params.facet_alpha) * clamp(dot(_678, half3(_1109)), half(0.0), half(1.0))) * half(64.0);
    half _1155 = (half(4096.0) * half(params.facet_alpha)) / dot(_1174, _1174);
    half _1185 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1191 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1219 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1109)), half(0.0), half(1.0));
    half _1222 = _1219 * _1219;
    half3 _1244 = fma(half3(float3(params.facet_diffuseColor)), _878, half4(_993).xyz * (mix(half4(_967).xxx, half4(_967).yyy, half3(float3(params.facet_f0))) * _986)) + min(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1222 * _1222) * _1219))) * min(min((_1155 * _1155) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1053, sqrt(fma(_928 * _928, _1191, _1185)), _928 * sqrt(fma(_1053 * _1053, _1191, _1185))), half(65504.0)), half(65504.0)), _986, half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1053), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1244, half(1.0)));
    return out;
}

