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
    half3 _908 = normalize(half3(in.v_normal));
    float3 _912 = fast::normalize(in.v_toEye);
    half _1042 = _908.y;
    half _1047 = _908.z;
    half _1052 = _908.x;
    half3 _1120 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1042)) + (half4(frame.sh[2]).xyz * _1047)) + (half4(frame.sh[3]).xyz * _1052)) + (((((half4(frame.sh[4]).xyz * (_1052 * _1042)) + (half4(frame.sh[5]).xyz * (_1042 * _1047))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1047, _1047, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1052 * _1047))) + (half4(frame.sh[8]).xyz * fma(_1052, _1052, half(-float(_1042 * _1042))))), half3(float3(0.0)));
    half _1170 = max(dot(_908, half3(_912)), half(9.9999997473787516355514526367188e-05));
    half3 _1174 = reflect(-half3(_912), _908);
    float4 _1209 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1170, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1228 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1209).y) - half(1.0)));
    float4 _1235 = facet_environment.sample(facet_environmentSmplr, float3(_1174), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1308 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1268 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1170, _1308)), level(0.0));
    half3 _1315 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1861 = half4(_1268);
    half _1281 = _1861.z;
    half _1283 = fma(half(-float(max(_1315.x, max(_1315.y, _1315.z)))), _1281, half(1.0));
    float4 _1322 = facet_environment.sample(facet_environmentSmplr, float3(_1174), level(_1308 * half(4.0)));
    half3 _967 = half4(frame.lightColor).xyz;
    float3 _1462 = fast::normalize(_912 + frame.lightDirection.xyz);
    half _1403 = clamp(dot(_908, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1407 = clamp(dot(_908, half3(_1462)), half(0.0), half(1.0));
    half3 _1502 = cross(_908, half3(_1462));
    half _1505 = _1407 * half(params.facet_alpha);
    half _1514 = half(params.facet_alpha) / fma(_1505, _1505, dot(_1502, _1502));
    half _1528 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1534 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1562 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1462)), half(0.0), half(1.0));
    half _1565 = _1562 * _1562;
    half _1645 = _1308 * _1308;
    half _1665 = half(8192.0) * fma(half(-float(_1403)), _1170, _1403 + _1170);
    half _1669 = half(1.0) / (_1645 * _1665);
    half3 _1710 = fma(half4(_1322).xyz, _1315 * _1281, fma(half3(float3(params.facet_diffuseColor)), _1120, half4(_1235).xyz * (mix(half4(_1209).xxx, half4(_1209).yyy, half3(float3(params.facet_f0))) * _1228)) * _1283) + (min(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1565 * _1565) * _1562))) * min(min((_1514 * _1514) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1403, sqrt(fma(_1170 * _1170, _1534, _1528)), _1170 * sqrt(fma(_1403 * _1403, _1534, _1528))), half(65504.0)), half(65504.0)), _1228, half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)) * ((_967 * _1403) * _1283), half3(float3(65504.0))) + min((_1315 * ((((fma(_1669, _1665, half(2.0)) * pow(max(fma(half(-float(_1407)), _1407, half(1.0)), half(0.0)), half(0.5) * (_1669 * _1665))) * half(0.15915493667125701904296875)) * (_1403 * (_1669 * (half(2048.0) * _1645)))) * half4(_1268).w)) * _967, half3(float3(65504.0))));
    out.fragColor = float4(half4(_1710, half(1.0)));
    return out;
}

