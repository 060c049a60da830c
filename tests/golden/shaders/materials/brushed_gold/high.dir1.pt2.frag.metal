#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float facet_perceptualRoughness;
    char _m3_pad[12];
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
    float3 v_worldPosition [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _771 = normalize(half3(in.v_normal));
    float3 _777 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1065 = max(dot(_771, half3(_777)), half(9.9999997473787516355514526367188e-05));
    float4 _1104 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1065, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1123 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1104).y) - half(1.0)));
    float4 _1135 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_777), _771)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1251 = fast::normalize(_777 + frame.lightDirection.xyz);
    half _1195 = clamp(dot(_771, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1291 = cross(_771, half3(_1251));
    half _1294 = clamp(dot(_771, half3(_1251)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1303 = half(params.facet_alpha) / fma(_1294, _1294, dot(_1291, _1291));
    half _1317 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1323 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1327 = sqrt(fma(_1065 * _1065, _1323, _1317));
    half _1351 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1251)), half(0.0), half(1.0));
    half _1354 = _1351 * _1351;
    half3 _1362 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1420 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1423 = dot(_1420, _1420);
    float3 _1428 = _1420 * rsqrt(fast::max(_1423, 9.9999999392252902907785028219223e-09));
    float _1432 = _1423 * float(frame.punctualLights[0].positionFalloff.w);
    float _1437 = fast::clamp(fma(-_1432, _1432, 1.0), 0.0, 1.0);
    float _1456 = fast::clamp(fma(dot(-_1428, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1575 = fast::normalize(_777 + _1428);
    half _1519 = clamp(dot(_771, half3(_1428)), half(0.0), half(1.0));
    half3 _1615 = cross(_771, half3(_1575));
    half _1618 = clamp(dot(_771, half3(_1575)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1627 = half(params.facet_alpha) / fma(_1618, _1618, dot(_1615, _1615));
    half _1675 = half(1.0) - clamp(dot(half3(_1428), half3(_1575)), half(0.0), half(1.0));
    half _1678 = _1675 * _1675;
    float3 _1744 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1747 = dot(_1744, _1744);
    float3 _1752 = _1744 * rsqrt(fast::max(_1747, 9.9999999392252902907785028219223e-09));
    float _1756 = _1747 * float(frame.punctualLights[1].positionFalloff.w);
    float _1761 = fast::clamp(fma(-_1756, _1756, 1.0), 0.0, 1.0);
    float _1780 = fast::clamp(fma(dot(-_1752, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1899 = fast::normalize(_777 + _1752);
    half _1843 = clamp(dot(_771, half3(_1752)), half(0.0), half(1.0));
    half3 _1939 = cross(_771, half3(_1899));
    half _1942 = clamp(dot(_771, half3(_1899)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1951 = half(params.facet_alpha) / fma(_1942, _1942, dot(_1939, _1939));
    half _1999 = half(1.0) - clamp(dot(half3(_1752), half3(_1899)), half(0.0), half(1.0));
    half _2002 = _1999 * _1999;
    half3 _2032 = (fma(half4(_1135).xyz, mix(half4(_1104).xxx, half4(_1104).yyy, half3(float3(params.facet_f0))) * _1123, min((((half3(float3(params.facet_f0)) + (_1362 * ((_1354 * _1354) * _1351))) * min(min((_1303 * _1303) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1195, _1327, _1065 * sqrt(fma(_1195 * _1195, _1323, _1317))), half(65504.0)), half(65504.0))) * _1123) * (half4(frame.lightColor).xyz * _1195), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1362 * ((_1678 * _1678) * _1675))) * min(min((_1627 * _1627) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1519, _1327, _1065 * sqrt(fma(_1519 * _1519, _1323, _1317))), half(65504.0)), half(65504.0))) * _1123) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1437) * half(_1437)) / fast::max(_1423, 9.9999997473787516355514526367188e-05)) * half(_1456)) * half(_1456)), float3(65504.0))) * _1519), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1362 * ((_2002 * _2002) * _1999))) * min(min((_1951 * _1951) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1843, _1327, _1065 * sqrt(fma(_1843 * _1843, _1323, _1317))), half(65504.0)), half(65504.0))) * _1123) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1761) * half(_1761)) / fast::max(_1747, 9.9999997473787516355514526367188e-05)) * half(_1780)) * half(_1780)), float3(65504.0))) * _1843), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2032, half(1.0)));
    return out;
}

