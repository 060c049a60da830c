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
    half3 _877 = normalize(half3(in.v_normal));
    float3 _881 = fast::normalize(in.v_toEye);
    half _1148 = max(dot(_877, half3(_881)), half(9.9999997473787516355514526367188e-05));
    half3 _1152 = reflect(-half3(_881), _877);
    float4 _1187 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1148, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1206 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1187).y) - half(1.0)));
    float4 _1216 = facet_environment.sample(facet_environmentSmplr, float3(_1152), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1263 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1269 = half(1.0) - _1148;
    half _1272 = _1269 * _1269;
    half _1276 = half(0.959999978542327880859375) * _1263;
    half _1283 = fma(half(0.039999999105930328369140625), _1263, _1276 * ((_1272 * _1272) * _1269));
    half _1288 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1298 = facet_environment.sample(facet_environmentSmplr, float3(_1152), level(_1288 * (half(4.0) * (half(2.0) - _1288))));
    float3 _1423 = fast::normalize(_881 + frame.lightDirection.xyz);
    half _1356 = clamp(dot(_877, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1360 = clamp(dot(_877, half3(_1423)), half(0.0), half(1.0));
    half _1364 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1423)), half(0.0), half(1.0));
    half3 _1482 = cross(_877, half3(_1423)) * half(64.0);
    half _1486 = (half(64.0) * half(params.facet_alpha)) * _1360;
    half _1489 = dot(_1482, _1482);
    half _1469 = (half(4096.0) * half(params.facet_alpha)) / fma(_1486, _1486, _1489);
    half _1501 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1507 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1535 = half(1.0) - _1364;
    half _1538 = _1535 * _1535;
    half _1543 = (_1538 * _1538) * _1535;
    half3 _1382 = half4(frame.lightColor).xyz * _1356;
    half _1583 = _1288 * _1288;
    half _1633 = (half(64.0) * _1583) * _1360;
    half _1593 = half(12.56637096405029296875) * max(_1364 * _1364, half(6.103515625e-05));
    half _1599 = (half(4096.0) * _1583) / (fma(_1633, _1633, _1489) * _1593);
    half3 _1684 = mix(half4(_1216).xyz * (mix(half4(_1187).xxx, half4(_1187).yyy, half3(float3(params.facet_f0))) * _1206), half4(_1298).xyz, half3(_1283)) + min(fma(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * _1543)) * min(min((_1469 * _1469) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1356, sqrt(fma(_1148 * _1148, _1507, _1501)), _1148 * sqrt(fma(_1356 * _1356, _1507, _1501))), half(65504.0)), half(65504.0))) * _1206, _1382 * (half(1.0) - _1283), _1382 * (min(_1599 * (_1599 * _1593), half(65504.0)) * fma(half(0.039999999105930328369140625), _1263, _1276 * _1543))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1684, half(1.0)));
    return out;
}

