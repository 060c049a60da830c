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
    float facet_clearCoat;
    float facet_clearCoatAlpha;
    float facet_clearCoatLod;
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
    half3 _867 = normalize(half3(in.v_normal));
    float3 _871 = fast::normalize(in.v_toEye);
    half _1139 = max(dot(_867, half3(_871)), half(9.9999997473787516355514526367188e-05));
    half3 _1143 = reflect(-half3(_871), _867);
    float4 _1178 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1139, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1197 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1178).y) - half(1.0)));
    float4 _1207 = facet_environment.sample(facet_environmentSmplr, float3(_1143), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1254 = half(1.0) - _1139;
    half _1257 = _1254 * _1254;
    half _1264 = fma(half(0.959999978542327880859375), (_1257 * _1257) * _1254, half(0.039999999105930328369140625));
    float4 _1242 = facet_environment.sample(facet_environmentSmplr, float3(_1143), level(params.facet_clearCoatLod));
    float3 _1392 = fast::normalize(_871 + frame.lightDirection.xyz);
    half _1324 = clamp(dot(_867, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1328 = clamp(dot(_867, half3(_1392)), half(0.0), half(1.0));
    half _1332 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1392)), half(0.0), half(1.0));
    half3 _1451 = cross(_867, half3(_1392)) * half(64.0);
    half _1455 = (half(64.0) * half(params.facet_alpha)) * _1328;
    half _1458 = dot(_1451, _1451);
    half _1438 = (half(4096.0) * half(params.facet_alpha)) / fma(_1455, _1455, _1458);
    half _1470 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1476 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1504 = half(1.0) - _1332;
    half _1507 = _1504 * _1504;
    half _1512 = (_1507 * _1507) * _1504;
    half _1601 = (half(64.0) * half(params.facet_clearCoatAlpha)) * _1328;
    half _1553 = half(12.56637096405029296875) * max(_1332 * _1332, half(6.103515625e-05));
    half _1559 = (half(4096.0) * half(params.facet_clearCoatAlpha)) / (fma(_1601, _1601, _1458) * _1553);
    half3 _1371 = min(((((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * _1512)) * min(min((_1438 * _1438) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1324, sqrt(fma(_1139 * _1139, _1476, _1470)), _1139 * sqrt(fma(_1324 * _1324, _1476, _1470))), half(65504.0)), half(65504.0))) * _1197) * fma(half(-float(_1264)), half(params.facet_clearCoat), half(1.0))) + half3(min(_1559 * (_1559 * _1553), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), (half(0.959999978542327880859375) * half(params.facet_clearCoat)) * _1512)), half3(float3(65504.0))) * (half4(frame.lightColor).xyz * _1324);
    out.fragColor = float4(half4(mix(half4(_1207).xyz * (mix(half4(_1178).xxx, half4(_1178).yyy, half3(float3(params.facet_f0))) * _1197), half4(_1242).xyz, half3(_1264 * half(params.facet_clearCoat))) + min(_1371, half3(float3(65504.0))), half(1.0)));
    return out;
}

