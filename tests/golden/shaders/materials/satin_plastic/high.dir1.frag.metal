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
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
    float facet_sheenRoughness;
    float facet_sheenAlpha;
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
    half3 _876 = normalize(half3(in.v_normal));
    float3 _880 = fast::normalize(in.v_toEye);
    half _1011 = _876.y;
    half _1016 = _876.z;
    half _1021 = _876.x;
    half3 _1089 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1011)) + (half4(frame.sh[2]).xyz * _1016)) + (half4(frame.sh[3]).xyz * _1021)) + (((((half4(frame.sh[4]).xyz * (_1021 * _1011)) + (half4(frame.sh[5]).xyz * (_1011 * _1016))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1016, _1016, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1021 * _1016))) + (half4(frame.sh[8]).xyz * fma(_1021, _1021, half(-float(_1011 * _1011))))), half3(float3(0.0)));
    half _1139 = max(dot(_876, half3(_880)), half(9.9999997473787516355514526367188e-05));
    half3 _1143 = reflect(-half3(_880), _876);
    float4 _1178 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1139, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1197 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1178).y) - half(1.0)));
    float4 _1207 = facet_environment.sample(facet_environmentSmplr, float3(_1143), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float4 _1239 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1139, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1751 = half4(_1239);
    half _1252 = _1751.z;
    half _1254 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _1252, half(1.0));
    float4 _1268 = facet_environment.sample(facet_environmentSmplr, float3(_1143), level(params.facet_sheenLod));
    half3 _935 = half4(frame.lightColor).xyz;
    float3 _1416 = fast::normalize(_880 + frame.lightDirection.xyz);
    half _1348 = clamp(dot(_876, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1352 = clamp(dot(_876, half3(_1416)), half(0.0), half(1.0));
    half4 _1481 = half4(cross(_876, half3(_1416)), half(params.facet_alpha) * _1352) * half(64.0);
    half _1462 = (half(4096.0) * half(params.facet_alpha)) / dot(_1481, _1481);
    half _1492 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1498 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1526 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1416)), half(0.0), half(1.0));
    half _1529 = _1526 * _1526;
    half _1570 = half(8192.0) * fma(half(-float(_1348)), _1139, _1348 + _1139);
    half _1574 = half(1.0) / (half(params.facet_sheenAlpha) * _1570);
    half3 _1397 = min(fma(fma((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * ((_1529 * _1529) * _1526))) * min(min((_1462 * _1462) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1348, sqrt(fma(_1139 * _1139, _1498, _1492)), _1139 * sqrt(fma(_1348 * _1348, _1498, _1492))), half(65504.0)), half(65504.0)), _1197, half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375)), (_935 * _1348) * _1254, (half3(float3(params.facet_sheenColor)) * ((((fma(_1574, _1570, half(2.0)) * pow(max(fma(half(-float(_1352)), _1352, half(1.0)), half(0.0)), half(0.5) * (_1574 * _1570))) * half(0.15915493667125701904296875)) * (_1348 * (_1574 * (half(2048.0) * half(params.facet_sheenAlpha))))) * half4(_1239).w)) * _935), half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_1268).xyz, half3(float3(params.facet_sheenColor)) * _1252, fma(half3(float3(params.facet_diffuseColor)), _1089, half4(_1207).xyz * (mix(half4(_1178).xxx, half4(_1178).yyy, half3(float3(params.facet_f0))) * _1197)) * _1254) + _1397, half(1.0)));
    return out;
}

