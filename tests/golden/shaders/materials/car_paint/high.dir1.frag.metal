#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
    packed_float3 facet_f0;
    float facet_alpha;
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    float facet_clearCoat;
    float facet_clearCoatAlpha;
    float facet_clearCoatLod;
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
    half3 _853 = normalize(half3(in.v_normal));
    float3 _857 = fast::normalize(in.v_toEye);
    half _1123 = max(dot(_853, half3(_857)), half(9.9999997473787516355514526367188e-05));
    half3 _1127 = reflect(-half3(_857), _853);
    float4 _1165 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1123, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1184 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1165).y) - half(1.0)));
    float4 _1141 = facet_environment.sample(facet_environmentSmplr, float3(_1127), level(params.facet_environmentLod));
    half _1230 = half(1.0) - _1123;
    half _1233 = _1230 * _1230;
    half _1240 = fma(half(0.959999978542327880859375), (_1233 * _1233) * _1230, half(0.039999999105930328369140625));
    float4 _1218 = facet_environment.sample(facet_environmentSmplr, float3(_1127), level(params.facet_clearCoatLod));
    half _1297 = clamp(dot(_853, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    float3 _1368 = fast::normalize(_857 + frame.lightDirection.xyz);
    half _1304 = clamp(dot(_853, half3(_1368)), half(0.0), half(1.0));
    half _1308 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1368)), half(0.0), half(1.0));
    half3 _1427 = cross(_853, half3(_1368)) * half(64.0);
    half _1431 = (half(64.0) * half(params.facet_alpha)) * _1304;
    half _1434 = dot(_1427, _1427);
    half _1414 = (half(4096.0) * half(params.facet_alpha)) / fma(_1431, _1431, _1434);
    half _1446 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1452 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1480 = half(1.0) - _1308;
    half _1483 = _1480 * _1480;
    half _1488 = (_1483 * _1483) * _1480;
    half _1577 = (half(64.0) * half(params.facet_clearCoatAlpha)) * _1304;
    half _1529 = half(12.56637096405029296875) * max(_1308 * _1308, half(6.103515625e-05));
    half _1535 = (half(4096.0) * half(params.facet_clearCoatAlpha)) / (fma(_1577, _1577, _1434) * _1529);
    half3 _1347 = min(((((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * _1488)) * min(min((_1414 * _1414) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1297, sqrt(fma(_1123 * _1123, _1452, _1446)), _1123 * sqrt(fma(_1297 * _1297, _1452, _1446))), half(65504.0)), half(65504.0))) * _1184) * fma(half(-float(_1240)), half(params.facet_clearCoat), half(1.0))) + half3(min(_1535 * (_1535 * _1529), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), (half(0.959999978542327880859375) * half(params.facet_clearCoat)) * _1488)), half3(float3(65504.0))) * (half4(frame.lightColor).xyz * _1297);
    out.fragColor = float4(half4(mix(half4(_1141).xyz * (mix(half4(_1165).xxx, half4(_1165).yyy, half3(float3(params.facet_f0))) * _1184), half4(_1218).xyz, half3(_1240 * half(params.facet_clearCoat))) + min(_1347, half3(float3(65504.0))), half(1.0)));
    return out;
}

