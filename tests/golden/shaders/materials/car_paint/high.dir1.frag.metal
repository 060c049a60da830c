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
    half _1127 = max(dot(_856, half3(_860)), half(9.9999997473787516355514526367188e-05));
    half3 _1131 = reflect(-half3(_860), _856);
    float4 _1166 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1127, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1185 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1166).y) - half(1.0)));
    float4 _1192 = facet_environment.sample(facet_environmentSmplr, float3(_1131), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1240 = half(1.0) - _1127;
    half _1243 = _1240 * _1240;
    half _1250 = fma(half(0.959999978542327880859375), (_1243 * _1243) * _1240, half(0.039999999105930328369140625));
    half _1255 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1260 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1267 = facet_environment.sample(facet_environmentSmplr, float3(_1131), level(_1260 * half(4.0)));
    float3 _1392 = fast::normalize(_860 + frame.lightDirection.xyz);
    half _1325 = clamp(dot(_856, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1329 = clamp(dot(_856, half3(_1392)), half(0.0), half(1.0));
    half _1333 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1392)), half(0.0), half(1.0));
    half3 _1432 = cross(_856, half3(_1392));
    half _1435 = _1329 * half(params.facet_alpha);
    half _1439 = dot(_1432, _1432);
    half _1444 = half(params.facet_alpha) / fma(_1435, _1435, _1439);
    half _1458 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1464 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1492 = half(1.0) - _1333;
    half _1495 = _1492 * _1492;
    half _1500 = (_1495 * _1495) * _1492;
    half3 _1351 = half4(frame.lightColor).xyz * _1325;
    half _1537 = _1260 * _1260;
    half _1543 = _1329 * _1537;
    half _1554 = max(_1333 * _1333, half(6.103515625e-05));
    half _1562 = (half(2048.0) * _1537) / (fma(_1543, _1543, _1439) * (_1554 * half(25735.927734375)));
    half3 _1625 = mix(half4(_1192).xyz * (mix(half4(_1166).xxx, half4(_1166).yyy, half3(float3(params.facet_f0))) * _1185), half4(_1267).xyz, half3(_1250 * _1255)) + min(fma(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * _1500)) * min(min((_1444 * _1444) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1325, sqrt(fma(_1127 * _1127, _1464, _1458)), _1127 * sqrt(fma(_1325 * _1325, _1464, _1458))), half(65504.0)), half(65504.0))) * _1185, _1351 * fma(half(-float(_1250)), _1255, half(1.0)), _1351 * (min(_1562 * (_1562 * (half(12.56637096405029296875) * _1554)), half(65504.0)) * (fma(half(0.959999978542327880859375), _1500, half(0.039999999105930328369140625)) * _1255))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1625, half(1.0)));
    return out;
}

