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
    half3 _874 = normalize(half3(in.v_normal));
    float3 _878 = fast::normalize(in.v_toEye);
    half _1145 = max(dot(_874, half3(_878)), half(9.9999997473787516355514526367188e-05));
    half3 _1149 = reflect(-half3(_878), _874);
    float4 _1184 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1145, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1203 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1184).y) - half(1.0)));
    float4 _1213 = facet_environment.sample(facet_environmentSmplr, float3(_1149), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1261 = half(1.0) - _1145;
    half _1264 = _1261 * _1261;
    half _1271 = fma(half(0.959999978542327880859375), (_1264 * _1264) * _1261, half(0.039999999105930328369140625));
    half _1276 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1281 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1291 = facet_environment.sample(facet_environmentSmplr, float3(_1149), level(_1281 * (half(4.0) * (half(2.0) - _1281))));
    float3 _1416 = fast::normalize(_878 + frame.lightDirection.xyz);
    half _1348 = clamp(dot(_874, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1352 = clamp(dot(_874, half3(_1416)), half(0.0), half(1.0));
    half _1356 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1416)), half(0.0), half(1.0));
    half3 _1475 = cross(_874, half3(_1416)) * half(64.0);
    half _1479 = (half(64.0) * half(params.facet_alpha)) * _1352;
    half _1482 = dot(_1475, _1475);
    half _1462 = (half(4096.0) * half(params.facet_alpha)) / fma(_1479, _1479, _1482);
    half _1494 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1500 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1528 = half(1.0) - _1356;
    half _1531 = _1528 * _1528;
    half _1536 = (_1531 * _1531) * _1528;
    half _1571 = _1281 * _1281;
    half _1630 = (half(64.0) * _1571) * _1352;
    half _1581 = half(12.56637096405029296875) * max(_1356 * _1356, half(6.103515625e-05));
    half _1587 = (half(4096.0) * _1571) / (fma(_1630, _1630, _1482) * _1581);
    half3 _1397 = min(min(((((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * _1536)) * min(min((_1462 * _1462) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1348, sqrt(fma(_1145 * _1145, _1500, _1494)), _1145 * sqrt(fma(_1348 * _1348, _1500, _1494))), half(65504.0)), half(65504.0))) * _1203) * fma(half(-float(_1271)), _1276, half(1.0))) + half3(min(_1587 * (_1587 * _1581), half(65504.0)) * fma(half(0.039999999105930328369140625), _1276, (half(0.959999978542327880859375) * _1276) * _1536)), half3(float3(65504.0))) * (half4(frame.lightColor).xyz * _1348), half3(float3(65504.0)));
    out.fragColor = float4(half4(mix(half4(_1213).xyz * (mix(half4(_1184).xxx, half4(_1184).yyy, half3(float3(params.facet_f0))) * _1203), half4(_1291).xyz, half3(_1271 * _1276)) + _1397, half(1.0)));
    return out;
}

