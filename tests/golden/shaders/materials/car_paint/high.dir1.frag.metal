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
    half3 _871 = normalize(half3(in.v_normal));
    float3 _875 = fast::normalize(in.v_toEye);
    half _1142 = max(dot(_871, half3(_875)), half(9.9999997473787516355514526367188e-05));
    half3 _1146 = reflect(-half3(_875), _871);
    float4 _1181 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1142, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1200 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1181).y) - half(1.0)));
    float4 _1210 = facet_environment.sample(facet_environmentSmplr, float3(_1146), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1258 = half(1.0) - _1142;
    half _1261 = _1258 * _1258;
    half _1268 = fma(half(0.959999978542327880859375), (_1261 * _1261) * _1258, half(0.039999999105930328369140625));
    half _1273 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1278 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1288 = facet_environment.sample(facet_environmentSmplr, float3(_1146), level(_1278 * (half(4.0) * (half(2.0) - _1278))));
    float3 _1413 = fast::normalize(_875 + frame.lightDirection.xyz);
    half _1346 = clamp(dot(_871, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1350 = clamp(dot(_871, half3(_1413)), half(0.0), half(1.0));
    half _1354 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1413)), half(0.0), half(1.0));
    half3 _1470 = cross(_871, half3(_1413));
    half _1474 = _1470.x;
    half4 _1478 = half4(_1474, _1470.yz, half(params.facet_alpha) * _1350) * half(64.0);
    half _1459 = (half(4096.0) * half(params.facet_alpha)) / dot(_1478, _1478);
    half _1489 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1495 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1523 = half(1.0) - _1354;
    half _1526 = _1523 * _1523;
    half _1531 = (_1526 * _1526) * _1523;
    half3 _1372 = half4(frame.lightColor).xyz * _1346;
    half _1570 = _1278 * _1278;
    half4 _1623 = half4(_1474, _1470.yz, _1570 * _1350) * half(64.0);
    half _1580 = half(12.56637096405029296875) * max(_1354 * _1354, half(6.103515625e-05));
    half _1586 = (half(4096.0) * _1570) / (dot(_1623, _1623) * _1580);
    half3 _1666 = mix(half4(_1210).xyz * (mix(half4(_1181).xxx, half4(_1181).yyy, half3(float3(params.facet_f0))) * _1200), half4(_1288).xyz, half3(_1268 * _1273)) + min(fma(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * _1531)) * min(min((_1459 * _1459) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1346, sqrt(fma(_1142 * _1142, _1495, _1489)), _1142 * sqrt(fma(_1346 * _1346, _1495, _1489))), half(65504.0)), half(65504.0))) * _1200, _1372 * fma(half(-float(_1268)), _1273, half(1.0)), _1372 * (min(_1586 * (_1586 * _1580), half(65504.0)) * (fma(half(0.959999978542327880859375), _1531, half(0.039999999105930328369140625)) * _1273))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1666, half(1.0)));
    return out;
}

