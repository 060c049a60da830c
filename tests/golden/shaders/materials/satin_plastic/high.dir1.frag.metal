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
    half3 _864 = normalize(half3(in.v_normal));
    float3 _868 = fast::normalize(in.v_toEye);
    half _998 = _864.y;
    half _1003 = _864.z;
    half _1008 = _864.x;
    half3 _1076 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _998)) + (half4(frame.sh[2]).xyz * _1003)) + (half4(frame.sh[3]).xyz * _1008)) + (((((half4(frame.sh[4]).xyz * (_1008 * _998)) + (half4(frame.sh[5]).xyz * (_998 * _1003))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1003, _1003, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1008 * _1003))) + (half4(frame.sh[8]).xyz * fma(_1008, _1008, half(-float(_998 * _998))))), half3(float3(0.0)));
    half _1126 = max(dot(_864, half3(_868)), half(9.9999997473787516355514526367188e-05));
    half3 _1130 = reflect(-half3(_868), _864);
    float4 _1165 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1126, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1184 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1165).y) - half(1.0)));
    float4 _1194 = facet_environment.sample(facet_environmentSmplr, float3(_1130), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1271 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1228 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1126, _1271)), level(0.0));
    half3 _1278 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1761 = half4(_1228);
    half _1241 = _1761.z;
    half _1243 = fma(half(-float(max(_1278.x, max(_1278.y, _1278.z)))), _1241, half(1.0));
    half _1287 = _1271 * _1271;
    float4 _1302 = facet_environment.sample(facet_environmentSmplr, float3(_1130), level(_1271 * (half(4.0) * (half(2.0) - _1271))));
    half3 _923 = half4(frame.lightColor).xyz;
    float3 _1427 = fast::normalize(_868 + frame.lightDirection.xyz);
    half _1359 = clamp(dot(_864, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1363 = clamp(dot(_864, half3(_1427)), half(0.0), half(1.0));
    half3 _1467 = cross(_864, half3(_1427));
    half _1470 = _1363 * half(params.facet_alpha);
    half _1479 = half(params.facet_alpha) / fma(_1470, _1470, dot(_1467, _1467));
    half _1493 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1499 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1527 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1427)), half(0.0), half(1.0));
    half _1530 = _1527 * _1527;
    half _1571 = half(8192.0) * fma(half(-float(_1359)), _1126, _1359 + _1126);
    half _1575 = half(1.0) / (_1287 * _1571);
    half3 _1408 = min(fma(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1530 * _1530) * _1527))) * min(min((_1479 * _1479) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1359, sqrt(fma(_1126 * _1126, _1499, _1493)), _1126 * sqrt(fma(_1359 * _1359, _1499, _1493))), half(65504.0)), half(65504.0)), _1184, half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)), (_923 * _1359) * _1243, (_1278 * ((((fma(_1575, _1571, half(2.0)) * pow(max(fma(half(-float(_1363)), _1363, half(1.0)), half(0.0)), half(0.5) * (_1575 * _1571))) * half(0.15915493667125701904296875)) * (_1359 * (_1575 * (half(2048.0) * _1287)))) * half4(_1228).w)) * _923), half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_1302).xyz, _1278 * _1241, fma(half3(float3(params.facet_diffuseColor)), _1076, half4(_1194).xyz * (mix(half4(_1165).xxx, half4(_1165).yyy, half3(float3(params.facet_f0))) * _1184)) * _1243) + _1408, half(1.0)));
    return out;
}

