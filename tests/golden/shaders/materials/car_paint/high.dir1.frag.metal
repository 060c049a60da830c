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
    half3 _856 = normalize(half3(in.v_normal));
    float3 _860 = fast::normalize(in.v_toEye);
    half _1130 = max(dot(_856, half3(_860)), half(9.9999997473787516355514526367188e-05));
    half3 _1134 = reflect(-half3(_860), _856);
    float4 _1169 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1130, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1188 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1169).y) - half(1.0)));
    float4 _1195 = facet_environment.sample(facet_environmentSmplr, float3(_1134), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1243 = half(1.0) - _1130;
    half _1246 = _1243 * _1243;
    half _1253 = fma(half(0.959999978542327880859375), (_1246 * _1246) * _1243, half(0.039999999105930328369140625));
    half _1258 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1263 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1270 = facet_environment.sample(facet_environmentSmplr, float3(_1134), level(_1263 * half(4.0)));
    float3 _1395 = fast::normalize(_860 + frame.lightDirection.xyz);
    half _1328 = clamp(dot(_856, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1332 = clamp(dot(_856, half3(_1395)), half(0.0), half(1.0));
    half _1336 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1395)), half(0.0), half(1.0));
    half3 _1435 = cross(_856, half3(_1395));
    half _1438 = _1332 * half(params.facet_alpha);
    half _1442 = dot(_1435, _1435);
    half _1447 = half(params.facet_alpha) / fma(_1438, _1438, _1442);
    half _1461 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1467 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1495 = half(1.0) - _1336;
    half _1498 = _1495 * _1495;
    half _1503 = (_1498 * _1498) * _1495;
    half3 _1354 = half4(frame.lightColor).xyz * _1328;
    half _1540 = _1263 * _1263;
    half _1546 = _1332 * _1540;
    half _1557 = max(_1336 * _1336, half(6.103515625e-05));
    half _1565 = (half(2048.0) * _1540) / (fma(_1546, _1546, _1442) * (_1557 * half(25735.927734375)));
    half3 _1628 = mix(half4(_1195).xyz * (mix(half4(_1169).xxx, half4(_1169).yyy, half3(float3(params.facet_f0))) * _1188), half4(_1270).xyz, half3(_1253 * _1258)) + min(fma(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * _1503)) * min(min((_1447 * _1447) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1328, sqrt(fma(_1130 * _1130, _1467, _1461)), _1130 * sqrt(fma(_1328 * _1328, _1467, _1461))), half(65504.0)), half(65504.0))) * _1188, _1354 * fma(half(-float(_1253)), _1258, half(1.0)), _1354 * (min(_1565 * (_1565 * (half(12.56637096405029296875) * _1557)), half(65504.0)) * (fma(half(0.959999978542327880859375), _1503, half(0.039999999105930328369140625)) * _1258))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1628, half(1.0)));
    return out;
}

