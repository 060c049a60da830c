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
    half3 _841 = normalize(half3(in.v_normal));
    float3 _845 = fast::normalize(in.v_toEye);
    half _1115 = max(dot(_841, half3(_845)), half(9.9999997473787516355514526367188e-05));
    half3 _1119 = reflect(-half3(_845), _841);
    float4 _1154 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1115, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1173 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1154).y) - half(1.0)));
    float4 _1180 = facet_environment.sample(facet_environmentSmplr, float3(_1119), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1228 = half(1.0) - _1115;
    half _1231 = _1228 * _1228;
    half _1238 = fma(half(0.959999978542327880859375), (_1231 * _1231) * _1228, half(0.039999999105930328369140625));
    half _1243 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1248 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1255 = facet_environment.sample(facet_environmentSmplr, float3(_1119), level(_1248 * half(4.0)));
    float3 _1380 = fast::normalize(_845 + frame.lightDirection.xyz);
    half _1313 = clamp(dot(_841, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1317 = clamp(dot(_841, half3(_1380)), half(0.0), half(1.0));
    half _1321 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1380)), half(0.0), half(1.0));
    half3 _1420 = cross(_841, half3(_1380));
    half _1423 = _1317 * half(params.facet_alpha);
    half _1427 = dot(_1420, _1420);
    half _1432 = half(params.facet_alpha) / fma(_1423, _1423, _1427);
    half _1446 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1452 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1480 = half(1.0) - _1321;
    half _1483 = _1480 * _1480;
    half _1488 = (_1483 * _1483) * _1480;
    half3 _1339 = half4(frame.lightColor).xyz * _1313;
    half _1529 = _1248 * _1248;
    half _1582 = _1317 * _1529;
    half _1591 = _1529 / fma(_1582, _1582, _1427);
    half3 _1361 = min(fma(((half3(float3(params.facet_f0)) + ((half3(float3(1.0)) - half3(float3(params.facet_f0))) * _1488)) * min(min((_1432 * _1432) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1313, sqrt(fma(_1115 * _1115, _1452, _1446)), _1115 * sqrt(fma(_1313 * _1313, _1452, _1446))), half(65504.0)), half(65504.0))) * _1173, _1339 * fma(half(-float(_1238)), _1243, half(1.0)), _1339 * (min(min((_1591 * _1591) * half(0.3183098733425140380859375), half(65504.0)) * (half(0.25) / max(_1321 * _1321, half(6.103515625e-05))), half(65504.0)) * (fma(half(0.959999978542327880859375), _1488, half(0.039999999105930328369140625)) * _1243))), half3(float3(65504.0)));
    out.fragColor = float4(half4(mix(half4(_1180).xyz * (mix(half4(_1154).xxx, half4(_1154).yyy, half3(float3(params.facet_f0))) * _1173), half4(_1255).xyz, half3(_1238 * _1243)) + _1361, half(1.0)));
    return out;
}

