#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
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
    half3 _861 = normalize(half3(in.v_normal));
    float3 _865 = fast::normalize(in.v_toEye);
    half _995 = _861.y;
    half _1000 = _861.z;
    half _1005 = _861.x;
    half3 _1073 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _995)) + (half4(frame.sh[2]).xyz * _1000)) + (half4(frame.sh[3]).xyz * _1005)) + (((((half4(frame.sh[4]).xyz * (_1005 * _995)) + (half4(frame.sh[5]).xyz * (_995 * _1000))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1000, _1000, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1005 * _1000))) + (half4(frame.sh[8]).xyz * fma(_1005, _1005, half(-float(_995 * _995))))), half3(float3(0.0)));
    half _1123 = max(dot(_861, half3(_865)), half(9.9999997473787516355514526367188e-05));
    half3 _1127 = reflect(-half3(_865), _861);
    float4 _1162 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1123, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1181 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1162).y) - half(1.0)));
    float4 _1188 = facet_environment.sample(facet_environmentSmplr, float3(_1127), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1265 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1222 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1123, _1265)), level(0.0));
    half3 _1272 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1750 = half4(_1222);
    half _1235 = _1750.z;
    half _1237 = fma(half(-float(max(_1272.x, max(_1272.y, _1272.z)))), _1235, half(1.0));
    half _1281 = _1265 * _1265;
    float4 _1293 = facet_environment.sample(facet_environmentSmplr, float3(_1127), level(_1265 * half(4.0)));
    half3 _920 = half4(frame.lightColor).xyz;
    float3 _1418 = fast::normalize(_865 + frame.lightDirection.xyz);
    half _1350 = clamp(dot(_861, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1354 = clamp(dot(_861, half3(_1418)), half(0.0), half(1.0));
    half3 _1458 = cross(_861, half3(_1418));
    half _1461 = _1354 * half(params.facet_alpha);
    half _1470 = half(params.facet_alpha) / fma(_1461, _1461, dot(_1458, _1458));
    half _1484 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1490 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1518 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1418)), half(0.0), half(1.0));
    half _1521 = _1518 * _1518;
    half _1562 = half(8192.0) * fma(half(-float(_1350)), _1123, _1350 + _1123);
    half _1566 = half(1.0) / (_1281 * _1562);
    half3 _1399 = min(fma(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1521 * _1521) * _1518))) * min(min((_1470 * _1470) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1350, sqrt(fma(_1123 * _1123, _1490, _1484)), _1123 * sqrt(fma(_1350 * _1350, _1490, _1484))), half(65504.0)), half(65504.0)), _1181, half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)), (_920 * _1350) * _1237, (_1272 * ((((fma(_1566, _1562, half(2.0)) * pow(max(fma(half(-float(_1354)), _1354, half(1.0)), half(0.0)), half(0.5) * (_1566 * _1562))) * half(0.15915493667125701904296875)) * (_1350 * (_1566 * (half(2048.0) * _1281)))) * half4(_1222).w)) * _920), half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_1293).xyz, _1272 * _1235, fma(half3(float3(params.facet_diffuseColor)), _1073, half4(_1188).xyz * (mix(half4(_1162).xxx, half4(_1162).yyy, half3(float3(params.facet_f0))) * _1181)) * _1237) + _1399, half(1.0)));
    return out;
}

