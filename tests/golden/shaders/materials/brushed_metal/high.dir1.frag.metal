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
    half3 _820 = normalize(half3(in.v_normal));
    float3 _824 = fast::normalize(in.v_toEye);
    half3 _945 = half4(in.v_tangent).xyz;
    half3 _952 = _945 - (_820 * dot(_820, _945));
    half _954 = _820.z;
    half3 _1631;
    if (float(abs(_954)) < 0.5)
    {
        _1631 = half3(-_820.y, _820.x, half(0.0));
    }
    else
    {
        _1631 = half3(half(0.0), -_954, _820.y);
    }
    half3 _981 = normalize(half3(select(float3(_1631), float3(_952), bool3(float(dot(_952, _952)) > 0.001000000047497451305389404296875))));
    half _844 = max(dot(_820, half3(_824)), half(9.9999997473787516355514526367188e-05));
    half3 _994 = cross(_820, _981);
    half2 _1000 = half2(float2(1.0)) / half2(params.facet_anisotropicAlpha);
    half2 _1002 = half2(params.facet_anisotropicAlpha) * half(128.0);
    half3 _1645 = select(_994, _981, bool3(params.facet_anisotropy >= 0.0));
    half _1257 = dot(_1645, half3(_824));
    half _1264 = fma(half(-params.facet_anisotropicBend), half(1.0) - _844, half(1.0));
    half _1267 = half(params.facet_anisotropicBend) * _1257;
    float4 _1306 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_844, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1335 = facet_environment.sample(facet_environmentSmplr, float3(((((_820 * _1264) + (_1645 * _1267)) * (half(512.0) * fma(_1264, _844, _1267 * _1257))) - (half3(_824) * (half(256.0) * fma(_1264, _1264, _1267 * _1267))))), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1442 = fast::normalize(_824 + frame.lightDirection.xyz);
    half _1391 = clamp(dot(_820, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1395 = clamp(dot(_820, half3(_1442)), half(0.0), half(1.0));
    half2 _1460 = half2(dot(_981, half3(_1442)), dot(_994, half3(_1442))) * _1000;
    half _1468 = half(1.0) / fma(_1395, _1395, dot(_1460, _1460));
    half _1509 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1442)), half(0.0), half(1.0));
    half _1512 = _1509 * _1509;
    half3 _1423 = min(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1512 * _1512) * _1509))) * min((((half(0.3183098733425140380859375) * (_1000.x * _1000.y)) * _1468) * _1468) * min(half(64.0) / fma(_1391, length(half3(_1002 * half2(dot(_981, half3(_824)), dot(_994, half3(_824))), half(128.0) * _844)), _844 * length(half3(_1002 * half2(dot(_981, half3(frame.lightDirection.xyz)), dot(_994, half3(frame.lightDirection.xyz))), half(128.0) * _1391))), half(65504.0)), half(65504.0))) * (half4(frame.lightColor).xyz * _1391), half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_1335).xyz, mix(half4(_1306).xxx, half4(_1306).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1306).y) - half(1.0)))), _1423), half(1.0)));
    return out;
}

