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
    half3 _841 = normalize(half3(in.v_normal));
    float3 _845 = fast::normalize(in.v_toEye);
    half3 _964 = half4(in.v_tangent).xyz;
    half3 _971 = _964 - (_841 * dot(_841, _964));
    half _973 = _841.z;
    half3 _1679;
    if (float(abs(_973)) < 0.5)
    {
        _1679 = half3(-_841.y, _841.x, half(0.0));
    }
    else
    {
        _1679 = half3(half(0.0), -_973, _841.y);
    }
    half3 _1000 = normalize(half3(select(float3(_1679), float3(_971), bool3(float(dot(_971, _971)) > 0.001000000047497451305389404296875))));
    half _865 = max(dot(_841, half3(_845)), half(9.9999997473787516355514526367188e-05));
    half3 _1013 = cross(_841, _1000);
    half _1064 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half2 _1059 = clamp(half2(half(1.0) + _1064, half(1.0) - _1064) * half(params.facet_alpha), half2(float2(0.007921000011265277862548828125)), half2(float2(1.0)));
    half2 _1019 = half2(float2(1.0)) / _1059;
    half2 _1021 = _1059 * half(128.0);
    half3 _1693 = select(_1013, _1000, bool3(float(_1064) >= 0.0));
    half _1293 = dot(_1693, half3(_845));
    half _1300 = min(abs(_1064) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _1305 = fma(half(-float(_1300)), half(1.0) - _865, half(1.0));
    half _1308 = _1300 * _1293;
    float4 _1348 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_865, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1379 = facet_environment.sample(facet_environmentSmplr, float3(((((_841 * _1305) + (_1693 * _1308)) * (half(512.0) * fma(_1305, _865, _1308 * _1293))) - (half3(_845) * (half(256.0) * fma(_1305, _1305, _1308 * _1308))))), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1486 = fast::normalize(_845 + frame.lightDirection.xyz);
    half _1435 = clamp(dot(_841, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1439 = clamp(dot(_841, half3(_1486)), half(0.0), half(1.0));
    half2 _1504 = half2(dot(_1000, half3(_1486)), dot(_1013, half3(_1486))) * _1019;
    half _1512 = half(1.0) / fma(_1439, _1439, dot(_1504, _1504));
    half _1553 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1486)), half(0.0), half(1.0));
    half _1556 = _1553 * _1553;
    half3 _1467 = min(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1556 * _1556) * _1553))) * min((((half(0.3183098733425140380859375) * (_1019.x * _1019.y)) * _1512) * _1512) * min(half(64.0) / fma(_1435, length(half3(_1021 * half2(dot(_1000, half3(_845)), dot(_1013, half3(_845))), half(128.0) * _865)), _865 * length(half3(_1021 * half2(dot(_1000, half3(frame.lightDirection.xyz)), dot(_1013, half3(frame.lightDirection.xyz))), half(128.0) * _1435))), half(65504.0)), half(65504.0))) * (half4(frame.lightColor).xyz * _1435), half3(float3(65504.0)));
    half3 _1586 = fma(half4(_1379).xyz, mix(half4(_1348).xxx, half4(_1348).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1348).y) - half(1.0)))), _1467);
    out.fragColor = float4(half4(_1586, half(1.0)));
    return out;
}

