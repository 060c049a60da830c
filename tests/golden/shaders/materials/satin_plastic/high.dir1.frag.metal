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
    half3 _866 = normalize(half3(in.v_normal));
    float3 _870 = fast::normalize(in.v_toEye);
    half _1000 = _866.y;
    half _1005 = _866.z;
    half _1010 = _866.x;
    half3 _1078 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1000)) + (half4(frame.sh[2]).xyz * _1005)) + (half4(frame.sh[3]).xyz * _1010)) + (((((half4(frame.sh[4]).xyz * (_1010 * _1000)) + (half4(frame.sh[5]).xyz * (_1000 * _1005))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1005, _1005, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1010 * _1005))) + (half4(frame.sh[8]).xyz * fma(_1010, _1010, half(-float(_1000 * _1000))))), half3(float3(0.0)));
    half _1128 = max(dot(_866, half3(_870)), half(9.9999997473787516355514526367188e-05));
    half3 _1132 = reflect(-half3(_870), _866);
    float4 _1167 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1128, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1186 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1167).y) - half(1.0)));
    float4 _1198 = facet_environment.sample(facet_environmentSmplr, float3(_1132), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1275 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1232 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1128, _1275)), level(0.0));
    half3 _1282 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1767 = half4(_1232);
    half _1245 = _1767.z;
    half _1247 = fma(half(-float(max(_1282.x, max(_1282.y, _1282.z)))), _1245, half(1.0));
    half _1291 = _1275 * _1275;
    float4 _1308 = facet_environment.sample(facet_environmentSmplr, float3(_1132), level(_1275 * (half(4.0) * (half(2.0) - _1275))));
    half3 _925 = half4(frame.lightColor).xyz;
    float3 _1433 = fast::normalize(_870 + frame.lightDirection.xyz);
    half _1365 = clamp(dot(_866, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1369 = clamp(dot(_866, half3(_1433)), half(0.0), half(1.0));
    half3 _1473 = cross(_866, half3(_1433));
    half _1476 = _1369 * half(params.facet_alpha);
    half _1485 = half(params.facet_alpha) / fma(_1476, _1476, dot(_1473, _1473));
    half _1499 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1505 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1533 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1433)), half(0.0), half(1.0));
    half _1536 = _1533 * _1533;
    half _1577 = half(8192.0) * fma(half(-float(_1365)), _1128, _1365 + _1128);
    half _1581 = half(1.0) / (_1291 * _1577);
    half3 _1414 = min(fma(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1536 * _1536) * _1533))) * min(min((_1485 * _1485) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1365, sqrt(fma(_1128 * _1128, _1505, _1499)), _1128 * sqrt(fma(_1365 * _1365, _1505, _1499))), half(65504.0)), half(65504.0)), _1186, half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)), (_925 * _1365) * _1247, (_1282 * ((((fma(_1581, _1577, half(2.0)) * pow(max(fma(half(-float(_1369)), _1369, half(1.0)), half(0.0)), half(0.5) * (_1581 * _1577))) * half(0.15915493667125701904296875)) * (_1365 * (_1581 * (half(2048.0) * _1291)))) * half4(_1232).w)) * _925), half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_1308).xyz, _1282 * _1245, fma(half3(float3(params.facet_diffuseColor)), _1078, half4(_1198).xyz * (mix(half4(_1167).xxx, half4(_1167).yyy, half3(float3(params.facet_f0))) * _1186)) * _1247) + _1414, half(1.0)));
    return out;
}

