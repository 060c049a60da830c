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
    half3 _867 = normalize(half3(in.v_normal));
    float3 _871 = fast::normalize(in.v_toEye);
    half _1138 = max(dot(_867, half3(_871)), half(9.9999997473787516355514526367188e-05));
    half3 _1142 = reflect(-half3(_871), _867);
    float4 _1177 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1138, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1196 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1177).y) - half(1.0)));
    float4 _1203 = facet_environment.sample(facet_environmentSmplr, float3(_1142), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1251 = half(1.0) - _1138;
    half _1254 = _1251 * _1251;
    half _1261 = fma(half(0.959999978542327880859375), (_1254 * _1254) * _1251, half(0.039999999105930328369140625));
    half _1266 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1271 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1278 = facet_environment.sample(facet_environmentSmplr, float3(_1142), level(_1271 * half(4.0)));
    float3 _1403 = fast::normalize(_871 + frame.lightDirection.xyz);
    half _1336 = clamp(dot(_867, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1340 = clamp(dot(_867, half3(_1403)), half(0.0), half(1.0));
    half _1344 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1403)), half(0.0), half(1.0));
    half3 _1460 = cross(_867, half3(_1403));
    half _1464 = _1460.x;
    half4 _1468 = half4(_1464, _1460.yz, half(params.facet_alpha) * _1340) * half(64.0);
    half _1449 = (half(4096.0) * half(params.facet_alpha)) / dot(_1468, _1468);
    half _1479 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1485 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1513 = half(1.0) - _1344;
    half _1516 = _1513 * _1513;
    half _1521 = (_1516 * _1516) * _1513;
    half3 _1362 = half4(frame.lightColor).xyz * _1336;
    half _1560 = _1271 * _1271;
    half4 _1613 = half4(_1464, _1460.yz, _1560 * _1340) * half(64.0);
    half _1570 = half(12.56637096405029296875) * max(_1344 * _1344, half(6.103515625e-05));
    half _1576 = (half(4096.0) * _1560) / (dot(_1613, _1613) * _1570);
    half3 _1656 = mix(half4(_1203).xyz * (mix(half4(_1177).xxx, half4(_1177).yyy, half3(float3(params.facet_f0))) * _1196), half4(_1278).xyz, half3(_1261 * _1266)) + min(fma(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * _1521)) * min(min((_1449 * _1449) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1336, sqrt(fma(_1138 * _1138, _1485, _1479)), _1138 * sqrt(fma(_1336 * _1336, _1485, _1479))), half(65504.0)), half(65504.0))) * _1196, _1362 * fma(half(-float(_1261)), _1266, half(1.0)), _1362 * (min(_1576 * (_1576 * _1570), half(65504.0)) * (fma(half(0.959999978542327880859375), _1521, half(0.039999999105930328369140625)) * _1266))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1656, half(1.0)));
    return out;
}

