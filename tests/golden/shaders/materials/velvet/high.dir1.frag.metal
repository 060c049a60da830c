#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    half3 _540 = normalize(half3(in.v_normal));
    float3 _544 = fast::normalize(in.v_toEye);
    half _664 = _540.y;
    half _669 = _540.z;
    half _674 = _540.x;
    half3 _742 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _664)) + (half4(frame.sh[2]).xyz * _669)) + (half4(frame.sh[3]).xyz * _674)) + (((((half4(frame.sh[4]).xyz * (_674 * _664)) + (half4(frame.sh[5]).xyz * (_664 * _669))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _669, _669, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_674 * _669))) + (half4(frame.sh[8]).xyz * fma(_674, _674, half(-float(_664 * _664))))), half3(float3(0.0)));
    half _782 = max(dot(_540, half3(_544)), half(9.9999997473787516355514526367188e-05));
    float4 _787 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_782, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _833 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1138 = half4(_787);
    half _800 = _1138.z;
    half _802 = fma(half(-float(max(_833.x, max(_833.y, _833.z)))), _800, half(1.0));
    float4 _840 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_544), _540)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _867 = dot(_540, half3(frame.lightDirection.xyz));
    half _869 = clamp(_867, half(0.0), half(1.0));
    half _883 = clamp(dot(_540, half3(fast::normalize(_544 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half _956 = half(8192.0) * fma(half(-float(_869)), _782, _869 + _782);
    half _960 = half(1.0) / (half(params.facet_alpha) * _956);
    half3 _922 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_867 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_869), half3(float3(0.0)), half3(float3(1.0)))) * _802) + (_833 * ((((fma(_960, _956, half(2.0)) * pow(max(fma(half(-float(_883)), _883, half(1.0)), half(0.0)), half(0.5) * (_960 * _956))) * half(0.15915493667125701904296875)) * (_869 * (_960 * (half(2048.0) * half(params.facet_alpha))))) * half4(_787).w))) * half4(frame.lightColor).xyz, half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_840).xyz, _833 * _800, (half3(float3(params.facet_diffuseColor)) * _742) * _802) + _922, half(1.0)));
    return out;
}

