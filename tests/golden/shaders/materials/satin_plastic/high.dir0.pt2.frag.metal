#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    half3 _985 = normalize(half3(in.v_normal));
    float3 _991 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1137 = _985.y;
    half _1142 = _985.z;
    half _1147 = _985.x;
    half3 _1215 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1137)) + (half4(frame.sh[2]).xyz * _1142)) + (half4(frame.sh[3]).xyz * _1147)) + (((((half4(frame.sh[4]).xyz * (_1147 * _1137)) + (half4(frame.sh[5]).xyz * (_1137 * _1142))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1142, _1142, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1147 * _1142))) + (half4(frame.sh[8]).xyz * fma(_1147, _1147, half(-float(_1137 * _1137))))), half3(float3(0.0)));
    half _1265 = max(dot(_985, half3(_991)), half(9.9999997473787516355514526367188e-05));
    half3 _1269 = reflect(-half3(_991), _985);
    float4 _1304 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1265, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1323 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1304).y) - half(1.0)));
    float4 _1330 = facet_environment.sample(facet_environmentSmplr, float3(_1269), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1407 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1364 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1265, _1407)), level(0.0));
    half3 _1414 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2444 = half4(_1364);
    half _1377 = _2444.z;
    half _1379 = fma(half(-float(max(_1414.x, max(_1414.y, _1414.z)))), _1377, half(1.0));
    half _1423 = _1407 * _1407;
    half4 _2448 = half4(_1364);
    half _1384 = _2448.w;
    float4 _1435 = facet_environment.sample(facet_environmentSmplr, float3(_1269), level(_1407 * half(4.0)));
    float3 _1472 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1475 = dot(_1472, _1472);
    float3 _1480 = _1472 * rsqrt(fast::max(_1475, 9.9999999392252902907785028219223e-09));
    float _1484 = _1475 * float(frame.punctualLights[0].positionFalloff.w);
    float _1489 = fast::clamp(fma(-_1484, _1484, 1.0), 0.0, 1.0);
    float _1508 = fast::clamp(fma(dot(-_1480, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1519 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1489) * half(_1489)) / fast::max(_1475, 9.9999997473787516355514526367188e-05)) * half(_1508)) * half(_1508)), float3(65504.0));
    float3 _1644 = fast::normalize(_991 + _1480);
    half _1576 = clamp(dot(_985, half3(_1480)), half(0.0), half(1.0));
    half _1580 = clamp(dot(_985, half3(_1644)), half(0.0), half(1.0));
    half _1685 = half(4096.0) * half(params.facet_alpha);
    half3 _1705 = cross(_985, half3(_1644)) * half(64.0);
    half _1708 = half(64.0) * half(params.facet_alpha);
    half _1709 = _1580 * _1708;
    half _1691 = _1685 / fma(_1709, _1709, dot(_1705, _1705));
    half _1724 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1730 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1734 = sqrt(fma(_1265 * _1265, _1730, _1724));
    half _1758 = half(1.0) - clamp(dot(half3(_1480), half3(_1644)), half(0.0), half(1.0));
    half _1761 = _1758 * _1758;
    half3 _1769 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1802 = half(8192.0) * fma(half(-float(_1576)), _1265, _1576 + _1265);
    half _1806 = half(1.0) / (_1423 * _1802);
    half _1813 = half(2048.0) * _1423;
    half3 _1617 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    half3 _1625 = min(fma(fma((half3(float3(params.facet_f0)) + (_1769 * ((_1761 * _1761) * _1758))) * min(min((_1691 * _1691) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1576, _1734, _1265 * sqrt(fma(_1576 * _1576, _1730, _1724))), half(65504.0)), half(65504.0)), _1323, _1617), (half3(_1519) * _1576) * _1379, (_1414 * ((((fma(_1806, _1802, half(2.0)) * pow(max(fma(half(-float(_1580)), _1580, half(1.0)), half(0.0)), half(0.5) * (_1806 * _1802))) * half(0.15915493667125701904296875)) * (_1576 * (_1806 * _1813))) * _1384)) * half3(_1519)), half3(float3(65504.0)));
    float3 _1877 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1880 = dot(_1877, _1877);
    float3 _1885 = _1877 * rsqrt(fast::max(_1880, 9.9999999392252902907785028219223e-09));
    float _1889 = _1880 * float(frame.punctualLights[1].positionFalloff.w);
    float _1894 = fast::clamp(fma(-_1889, _1889, 1.0), 0.0, 1.0);
    float _1913 = fast::clamp(fma(dot(-_1885, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1924 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1894) * half(_1894)) / fast::max(_1880, 9.9999997473787516355514526367188e-05)) * half(_1913)) * half(_1913)), float3(65504.0));
    float3 _2049 = fast::normalize(_991 + _1885);
    half _1981 = clamp(dot(_985, half3(_1885)), half(0.0), half(1.0));
    half _1985 = clamp(dot(_985, half3(_2049)), half(0.0), half(1.0));
    half3 _2110 = cross(_985, half3(_2049)) * half(64.0);
    half _2114 = _1985 * _1708;
    half _2096 = _1685 / fma(_2114, _2114, dot(_2110, _2110));
    half _2163 = half(1.0) - clamp(dot(half3(_1885), half3(_2049)), half(0.0), half(1.0));
    half _2166 = _2163 * _2163;
    half _2207 = half(8192.0) * fma(half(-float(_1981)), _1265, _1981 + _1265);
    half _2211 = half(1.0) / (_1423 * _2207);
    half3 _2030 = min(fma(fma((half3(float3(params.facet_f0)) + (_1769 * ((_2166 * _2166) * _2163))) * min(min((_2096 * _2096) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1981, _1734, _1265 * sqrt(fma(_1981 * _1981, _1730, _1724))), half(65504.0)), half(65504.0)), _1323, _1617), (half3(_1924) * _1981) * _1379, (_1414 * ((((fma(_2211, _2207, half(2.0)) * pow(max(fma(half(-float(_1985)), _1985, half(1.0)), half(0.0)), half(0.5) * (_2211 * _2207))) * half(0.15915493667125701904296875)) * (_1981 * (_2211 * _1813))) * _1384)) * half3(_1924)), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_1435).xyz, _1414 * _1377, fma(half3(float3(params.facet_diffuseColor)), _1215, half4(_1330).xyz * (mix(half4(_1304).xxx, half4(_1304).yyy, half3(float3(params.facet_f0))) * _1323)) * _1379) + _1625) + _2030, half(1.0)));
    return out;
}

