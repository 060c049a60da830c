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
    half3 _787 = normalize(half3(in.v_normal));
    float3 _793 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1060 = max(dot(_787, half3(_793)), half(9.9999997473787516355514526367188e-05));
    float4 _1099 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1060, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1118 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1099).y) - half(1.0)));
    float4 _1125 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_793), _787)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1170 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1173 = dot(_1170, _1170);
    float3 _1178 = _1170 * rsqrt(fast::max(_1173, 9.9999999392252902907785028219223e-09));
    float _1182 = _1173 * float(frame.punctualLights[0].positionFalloff.w);
    float _1187 = fast::clamp(fma(-_1182, _1182, 1.0), 0.0, 1.0);
    float _1206 = fast::clamp(fma(dot(-_1178, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1325 = fast::normalize(_793 + _1178);
    half _1269 = clamp(dot(_787, half3(_1178)), half(0.0), half(1.0));
    half _1366 = half(4096.0) * half(params.facet_alpha);
    half3 _1386 = cross(_787, half3(_1325)) * half(64.0);
    half _1389 = half(64.0) * half(params.facet_alpha);
    half _1390 = clamp(dot(_787, half3(_1325)), half(0.0), half(1.0)) * _1389;
    half _1372 = _1366 / fma(_1390, _1390, dot(_1386, _1386));
    half _1405 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1411 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1415 = sqrt(fma(_1060 * _1060, _1411, _1405));
    half _1439 = half(1.0) - clamp(dot(half3(_1178), half3(_1325)), half(0.0), half(1.0));
    half _1442 = _1439 * _1439;
    half3 _1450 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1508 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1511 = dot(_1508, _1508);
    float3 _1516 = _1508 * rsqrt(fast::max(_1511, 9.9999999392252902907785028219223e-09));
    float _1520 = _1511 * float(frame.punctualLights[1].positionFalloff.w);
    float _1525 = fast::clamp(fma(-_1520, _1520, 1.0), 0.0, 1.0);
    float _1544 = fast::clamp(fma(dot(-_1516, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1663 = fast::normalize(_793 + _1516);
    half _1607 = clamp(dot(_787, half3(_1516)), half(0.0), half(1.0));
    half3 _1724 = cross(_787, half3(_1663)) * half(64.0);
    half _1728 = clamp(dot(_787, half3(_1663)), half(0.0), half(1.0)) * _1389;
    half _1710 = _1366 / fma(_1728, _1728, dot(_1724, _1724));
    half _1777 = half(1.0) - clamp(dot(half3(_1516), half3(_1663)), half(0.0), half(1.0));
    half _1780 = _1777 * _1777;
    half3 _1810 = fma(half4(_1125).xyz, mix(half4(_1099).xxx, half4(_1099).yyy, half3(float3(params.facet_f0))) * _1118, min((((half3(float3(params.facet_f0)) + (_1450 * ((_1442 * _1442) * _1439))) * min(min((_1372 * _1372) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1269, _1415, _1060 * sqrt(fma(_1269 * _1269, _1411, _1405))), half(65504.0)), half(65504.0))) * _1118) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1187) * half(_1187)) / fast::max(_1173, 9.9999997473787516355514526367188e-05)) * half(_1206)) * half(_1206)), float3(65504.0))) * _1269), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1450 * ((_1780 * _1780) * _1777))) * min(min((_1710 * _1710) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1607, _1415, _1060 * sqrt(fma(_1607 * _1607, _1411, _1405))), half(65504.0)), half(65504.0))) * _1118) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1525) * half(_1525)) / fast::max(_1511, 9.9999997473787516355514526367188e-05)) * half(_1544)) * half(_1544)), float3(65504.0))) * _1607), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1810, half(1.0)));
    return out;
}

