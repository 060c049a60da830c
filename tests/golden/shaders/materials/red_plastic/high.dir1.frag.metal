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
    half3 _665 = normalize(half3(in.v_normal));
    float3 _669 = fast::normalize(in.v_toEye);
    half _787 = _665.y;
    half _792 = _665.z;
    half _797 = _665.x;
    half3 _865 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _787)) + (half4(frame.sh[2]).xyz * _792)) + (half4(frame.sh[3]).xyz * _797)) + (((((half4(frame.sh[4]).xyz * (_797 * _787)) + (half4(frame.sh[5]).xyz * (_787 * _792))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _792, _792, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_797 * _792))) + (half4(frame.sh[8]).xyz * fma(_797, _797, half(-float(_787 * _787))))), half3(float3(0.0)));
    half _915 = max(dot(_665, half3(_669)), half(9.9999997473787516355514526367188e-05));
    float4 _954 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_915, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _973 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_954).y) - half(1.0)));
    float4 _985 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_669), _665)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1101 = fast::normalize(_669 + frame.lightDirection.xyz);
    half _1045 = clamp(dot(_665, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1141 = cross(_665, half3(_1101));
    half _1144 = clamp(dot(_665, half3(_1101)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1153 = half(params.facet_alpha) / fma(_1144, _1144, dot(_1141, _1141));
    half _1167 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1173 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1201 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1101)), half(0.0), half(1.0));
    half _1204 = _1201 * _1201;
    half3 _1226 = fma(half3(float3(params.facet_diffuseColor)), _865, half4(_985).xyz * (mix(half4(_954).xxx, half4(_954).yyy, half3(float3(params.facet_f0))) * _973)) + min(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1204 * _1204) * _1201))) * min(min((_1153 * _1153) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1045, sqrt(fma(_915 * _915, _1173, _1167)), _915 * sqrt(fma(_1045 * _1045, _1173, _1167))), half(65504.0)), half(65504.0)), _973, half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1045), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1226, half(1.0)));
    return out;
}

