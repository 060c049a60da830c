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
    half3 _880 = normalize(half3(in.v_normal));
    float3 _884 = fast::normalize(in.v_toEye);
    half _1014 = _880.y;
    half _1019 = _880.z;
    half _1024 = _880.x;
    half3 _1092 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1014)) + (half4(frame.sh[2]).xyz * _1019)) + (half4(frame.sh[3]).xyz * _1024)) + (((((half4(frame.sh[4]).xyz * (_1024 * _1014)) + (half4(frame.sh[5]).xyz * (_1014 * _1019))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1019, _1019, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1024 * _1019))) + (half4(frame.sh[8]).xyz * fma(_1024, _1024, half(-float(_1014 * _1014))))), half3(float3(0.0)));
    half _1142 = max(dot(_880, half3(_884)), half(9.9999997473787516355514526367188e-05));
    half3 _1146 = reflect(-half3(_884), _880);
    float4 _1181 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1142, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1200 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1181).y) - half(1.0)));
    float4 _1207 = facet_environment.sample(facet_environmentSmplr, float3(_1146), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1284 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1241 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1142, _1284)), level(0.0));
    half3 _1291 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1778 = half4(_1241);
    half _1254 = _1778.z;
    half _1256 = fma(half(-float(max(_1291.x, max(_1291.y, _1291.z)))), _1254, half(1.0));
    half _1300 = _1284 * _1284;
    float4 _1312 = facet_environment.sample(facet_environmentSmplr, float3(_1146), level(_1284 * half(4.0)));
    half3 _939 = half4(frame.lightColor).xyz;
    float3 _1437 = fast::normalize(_884 + frame.lightDirection.xyz);
    half _1369 = clamp(dot(_880, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1373 = clamp(dot(_880, half3(_1437)), half(0.0), half(1.0));
    half4 _1502 = half4(cross(_880, half3(_1437)), half(params.facet_alpha) * _1373) * half(64.0);
    half _1483 = (half(4096.0) * half(params.facet_alpha)) / dot(_1502, _1502);
    half _1513 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1519 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1547 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1437)), half(0.0), half(1.0));
    half _1550 = _1547 * _1547;
    half _1591 = half(8192.0) * fma(half(-float(_1369)), _1142, _1369 + _1142);
    half _1595 = half(1.0) / (_1300 * _1591);
    half3 _1418 = min(fma(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1550 * _1550) * _1547))) * min(min((_1483 * _1483) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1369, sqrt(fma(_1142 * _1142, _1519, _1513)), _1142 * sqrt(fma(_1369 * _1369, _1519, _1513))), half(65504.0)), half(65504.0)), _1200, half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)), (_939 * _1369) * _1256, (_1291 * ((((fma(_1595, _1591, half(2.0)) * pow(max(fma(half(-float(_1373)), _1373, half(1.0)), half(0.0)), half(0.5) * (_1595 * _1591))) * half(0.15915493667125701904296875)) * (_1369 * (_1595 * (half(2048.0) * _1300)))) * half4(_1241).w)) * _939), half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_1312).xyz, _1291 * _1254, fma(half3(float3(params.facet_diffuseColor)), _1092, half4(_1207).xyz * (mix(half4(_1181).xxx, half4(_1181).yyy, half3(float3(params.facet_f0))) * _1200)) * _1256) + _1418, half(1.0)));
    return out;
}

