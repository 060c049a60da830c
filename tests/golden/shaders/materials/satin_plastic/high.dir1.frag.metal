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
    half3 _883 = normalize(half3(in.v_normal));
    float3 _887 = fast::normalize(in.v_toEye);
    half _1017 = _883.y;
    half _1022 = _883.z;
    half _1027 = _883.x;
    half3 _1095 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1017)) + (half4(frame.sh[2]).xyz * _1022)) + (half4(frame.sh[3]).xyz * _1027)) + (((((half4(frame.sh[4]).xyz * (_1027 * _1017)) + (half4(frame.sh[5]).xyz * (_1017 * _1022))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1022, _1022, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1027 * _1022))) + (half4(frame.sh[8]).xyz * fma(_1027, _1027, half(-float(_1017 * _1017))))), half3(float3(0.0)));
    half _1145 = max(dot(_883, half3(_887)), half(9.9999997473787516355514526367188e-05));
    half3 _1149 = reflect(-half3(_887), _883);
    float4 _1184 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1145, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1203 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1184).y) - half(1.0)));
    float4 _1213 = facet_environment.sample(facet_environmentSmplr, float3(_1149), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1290 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1247 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1145, _1290)), level(0.0));
    half3 _1297 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1789 = half4(_1247);
    half _1260 = _1789.z;
    half _1262 = fma(half(-float(max(_1297.x, max(_1297.y, _1297.z)))), _1260, half(1.0));
    half _1306 = _1290 * _1290;
    float4 _1321 = facet_environment.sample(facet_environmentSmplr, float3(_1149), level(_1290 * (half(4.0) * (half(2.0) - _1290))));
    half3 _942 = half4(frame.lightColor).xyz;
    float3 _1446 = fast::normalize(_887 + frame.lightDirection.xyz);
    half _1378 = clamp(dot(_883, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1382 = clamp(dot(_883, half3(_1446)), half(0.0), half(1.0));
    half4 _1511 = half4(cross(_883, half3(_1446)), half(params.facet_alpha) * _1382) * half(64.0);
    half _1492 = (half(4096.0) * half(params.facet_alpha)) / dot(_1511, _1511);
    half _1522 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1528 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1556 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1446)), half(0.0), half(1.0));
    half _1559 = _1556 * _1556;
    half _1600 = half(8192.0) * fma(half(-float(_1378)), _1145, _1378 + _1145);
    half _1604 = half(1.0) / (_1306 * _1600);
    half3 _1427 = min(fma(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1559 * _1559) * _1556))) * min(min((_1492 * _1492) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1378, sqrt(fma(_1145 * _1145, _1528, _1522)), _1145 * sqrt(fma(_1378 * _1378, _1528, _1522))), half(65504.0)), half(65504.0)), _1203, half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)), (_942 * _1378) * _1262, (_1297 * ((((fma(_1604, _1600, half(2.0)) * pow(max(fma(half(-float(_1382)), _1382, half(1.0)), half(0.0)), half(0.5) * (_1604 * _1600))) * half(0.15915493667125701904296875)) * (_1378 * (_1604 * (half(2048.0) * _1306)))) * half4(_1247).w)) * _942), half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_1321).xyz, _1297 * _1260, fma(half3(float3(params.facet_diffuseColor)), _1095, half4(_1213).xyz * (mix(half4(_1184).xxx, half4(_1184).yyy, half3(float3(params.facet_f0))) * _1203)) * _1262) + _1427, half(1.0)));
    return out;
}

