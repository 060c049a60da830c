#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float anisotropy;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
    packed_float3 facet_f0;
    float facet_alpha;
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    float facet_anisotropy;
    float facet_anisotropicBend;
    float2 facet_anisotropicAlpha;
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
    float4 v_tangent [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _805 = normalize(half3(in.v_normal));
    float3 _809 = fast::normalize(in.v_toEye);
    half3 _930 = half4(in.v_tangent).xyz;
    half3 _937 = _930 - (_805 * dot(_805, _930));
    half _939 = _805.z;
    half3 _1606;
    if (float(abs(_939)) < 0.5)
    {
        _1606 = half3(-_805.y, _805.x, half(0.0));
    }
    else
    {
        _1606 = half3(half(0.0), -_939, _805.y);
    }
    half3 _966 = normalize(half3(select(float3(_1606), float3(_937), bool3(float(dot(_937, _937)) > 0.001000000047497451305389404296875))));
    half _829 = max(dot(_805, half3(_809)), half(9.9999997473787516355514526367188e-05));
    half3 _979 = cross(_805, _966);
    half2 _985 = half2(float2(1.0)) / half2(params.facet_anisotropicAlpha);
    half2 _987 = half2(params.facet_anisotropicAlpha) * half(128.0);
    half3 _1620 = select(_979, _966, bool3(params.facet_anisotropy >= 0.0));
    half _1243 = dot(_1620, half3(_809));
    half _1250 = fma(half(-params.facet_anisotropicBend), half(1.0) - _829, half(1.0));
    half _1253 = half(params.facet_anisotropicBend) * _1243;
    float4 _1292 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_829, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1200 = facet_environment.sample(facet_environmentSmplr, float3(((((_805 * _1250) + (_1620 * _1253)) * (half(512.0) * fma(_1250, _829, _1253 * _1243))) - (half3(_809) * (half(256.0) * fma(_1250, _1250, _1253 * _1253))))), level(params.facet_environmentLod));
    half _1363 = clamp(dot(_805, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    float3 _1417 = fast::normalize(_809 + frame.lightDirection.xyz);
    half _1370 = clamp(dot(_805, half3(_1417)), half(0.0), half(1.0));
    half2 _1435 = half2(dot(_966, half3(_1417)), dot(_979, half3(_1417))) * _985;
    half _1443 = half(1.0) / fma(_1370, _1370, dot(_1435, _1435));
    half _1484 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1417)), half(0.0), half(1.0));
    half _1487 = _1484 * _1484;
    half3 _1398 = min(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1487 * _1487) * _1484))) * min((((half(0.3183098733425140380859375) * (_985.x * _985.y)) * _1443) * _1443) * min(half(64.0) / fma(_1363, length(half3(_987 * half2(dot(_966, half3(_809)), dot(_979, half3(_809))), half(128.0) * _829)), _829 * length(half3(_987 * half2(dot(_966, half3(frame.lightDirection.xyz)), dot(_979, half3(frame.lightDirection.xyz))), half(128.0) * _1363))), half(65504.0)), half(65504.0))) * (half4(frame.lightColor).xyz * _1363), half3(float3(65504.0)));
    half3 _1517 = fma(half4(_1200).xyz, mix(half4(_1292).xxx, half4(_1292).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1292).y) - half(1.0)))), _1398);
    out.fragColor = float4(half4(_1517, half(1.0)));
    return out;
}

