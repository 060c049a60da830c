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
    half3 _870 = normalize(half3(in.v_normal));
    float3 _874 = fast::normalize(in.v_toEye);
    half _1141 = max(dot(_870, half3(_874)), half(9.9999997473787516355514526367188e-05));
    half3 _1145 = reflect(-half3(_874), _870);
    float4 _1180 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1141, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1199 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1180).y) - half(1.0)));
    float4 _1206 = facet_environment.sample(facet_environmentSmplr, float3(_1145), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1254 = half(1.0) - _1141;
    half _1257 = _1254 * _1254;
    half _1264 = fma(half(0.959999978542327880859375), (_1257 * _1257) * _1254, half(0.039999999105930328369140625));
    half _1269 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1274 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1281 = facet_environment.sample(facet_environmentSmplr, float3(_1145), level(_1274 * half(4.0)));
    float3 _1406 = fast::normalize(_874 + frame.lightDirection.xyz);
    half _1339 = clamp(dot(_870, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1343 = clamp(dot(_870, half3(_1406)), half(0.0), half(1.0));
    half _1347 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1406)), half(0.0), half(1.0));
    half3 _1467 = cross(_870, half3(_1406)) * half(64.0);
    half _1471 = _1343 * (half(64.0) * half(params.facet_alpha));
    half _1474 = dot(_1467, _1467);
    half _1453 = (half(4096.0) * half(params.facet_alpha)) / fma(_1471, _1471, _1474);
    half _1486 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1492 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1520 = half(1.0) - _1347;
    half _1523 = _1520 * _1520;
    half _1528 = (_1523 * _1523) * _1520;
    half3 _1365 = half4(frame.lightColor).xyz * _1339;
    half _1567 = _1274 * _1274;
    half _1618 = _1343 * (half(64.0) * _1567);
    half _1577 = half(12.56637096405029296875) * max(_1347 * _1347, half(6.103515625e-05));
    half _1583 = (half(4096.0) * _1567) / (fma(_1618, _1618, _1474) * _1577);
    half3 _1665 = mix(half4(_1206).xyz * (mix(half4(_1180).xxx, half4(_1180).yyy, half3(float3(params.facet_f0))) * _1199), half4(_1281).xyz, half3(_1264 * _1269)) + min(fma(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * _1528)) * min(min((_1453 * _1453) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1339, sqrt(fma(_1141 * _1141, _1492, _1486)), _1141 * sqrt(fma(_1339 * _1339, _1492, _1486))), half(65504.0)), half(65504.0))) * _1199, _1365 * fma(half(-float(_1264)), _1269, half(1.0)), _1365 * (min(_1583 * (_1583 * _1577), half(65504.0)) * (fma(half(0.959999978542327880859375), _1528, half(0.039999999105930328369140625)) * _1269))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1665, half(1.0)));
    return out;
}

