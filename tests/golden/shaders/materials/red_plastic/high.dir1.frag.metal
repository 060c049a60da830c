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
    half _781 = _659.y;
    half _786 = _659.z;
    half _791 = _659.x;
    half3 _859 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _781)) + (half4(frame.sh[2]).xyz * _786)) + (half4(frame.sh[3]).xyz * _791)) + (((((half4(frame.sh[4]).xyz * (_791 * _781)) + (half4(frame.sh[5]).xyz * (_781 * _786))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _786, _786, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_791 * _786))) + (half4(frame.sh[8]).xyz * fma(_791, _791, half(-float(_781 * _781))))), half3(float3(0.0)));
    half _909 = max(dot(_659, half3(_663)), half(9.9999997473787516355514526367188e-05));
    float4 _948 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_909, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _967 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_948).y) - half(1.0)));
    float4 _974 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_663), _659)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1090 = fast::normalize(_663 + frame.lightDirection.xyz);
    half _1034 = clamp(dot(_659, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1130 = cross(_659, half3(_1090));
    half _1133 = clamp(dot(_659, half3(_1090)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1142 = half(params.facet_alpha) / fma(_1133, _1133, dot(_1130, _1130));
    half _1156 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1162 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1190 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1090)), half(0.0), half(1.0));
    half _1193 = _1190 * _1190;
    half3 _1215 = fma(half3(float3(params.facet_diffuseColor)), _859, half4(_974).xyz * (mix(half4(_948).xxx, half4(_948).yyy, half3(float3(params.facet_f0))) * _967)) + min(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1193 * _1193) * _1190))) * min(min((_1142 * _1142) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1034, sqrt(fma(_909 * _909, _1162, _1156)), _909 * sqrt(fma(_1034 * _1034, _1162, _1156))), half(65504.0)), half(65504.0)), _967, half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1034), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1215, half(1.0)));
    return out;
}

