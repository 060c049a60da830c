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
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
    float facet_sheenRoughness;
    float facet_sheenAlpha;
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
    half3 _977 = normalize(half3(in.v_normal));
    float3 _983 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1151 = _977.y;
    half _1156 = _977.z;
    half _1161 = _977.x;
    half3 _1229 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1151)) + (half4(frame.sh[2]).xyz * _1156)) + (half4(frame.sh[3]).xyz * _1161)) + (((((half4(frame.sh[4]).xyz * (_1161 * _1151)) + (half4(frame.sh[5]).xyz * (_1151 * _1156))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1156, _1156, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1161 * _1156))) + (half4(frame.sh[8]).xyz * fma(_1161, _1161, half(-float(_1151 * _1151))))), half3(float3(0.0)));
    half _1279 = max(dot(_977, half3(_983)), half(9.9999997473787516355514526367188e-05));
    half3 _1283 = reflect(-half3(_983), _977);
    float4 _1318 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1279, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1337 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1318).y) - half(1.0)));
    float4 _1347 = facet_environment.sample(facet_environmentSmplr, float3(_1283), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float4 _1379 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1279, half(params.facet_sheenRoughness))), level(0.0));
    half4 _2745 = half4(_1379);
    half _1392 = _2745.z;
    half _1394 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _1392, half(1.0));
    half4 _2749 = half4(_1379);
    half _1399 = _2749.w;
    float4 _1408 = facet_environment.sample(facet_environmentSmplr, float3(_1283), level(params.facet_sheenLod));
    half3 _1038 = half4(frame.lightColor).xyz;
    float3 _1556 = fast::normalize(_983 + frame.lightDirection.xyz);
    half _1488 = clamp(dot(_977, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1492 = clamp(dot(_977, half3(_1556)), half(0.0), half(1.0));
    half _1596 = half(4096.0) * half(params.facet_alpha);
    half4 _1621 = half4(cross(_977, half3(_1556)), half(params.facet_alpha) * _1492) * half(64.0);
    half _1602 = _1596 / dot(_1621, _1621);
    half _1632 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1638 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1642 = sqrt(fma(_1279 * _1279, _1638, _1632));
    half _1666 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1556)), half(0.0), half(1.0));
    half _1669 = _1666 * _1666;
    half3 _1677 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1710 = half(8192.0) * fma(half(-float(_1488)), _1279, _1488 + _1279);
    half _1714 = half(1.0) / (half(params.facet_sheenAlpha) * _1710);
    half _1721 = half(2048.0) * half(params.facet_sheenAlpha);
    half3 _1529 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    half3 _1537 = min(fma(fma((half3(float3(params.facet_f0)) + (_1677 * ((_1669 * _1669) * _1666))) * min(min((_1602 * _1602) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1488, _1642, _1279 * sqrt(fma(_1488 * _1488, _1638, _1632))), half(65504.0)), half(65504.0)), _1337, _1529), (_1038 * _1488) * _1394, (half3(float3(params.facet_sheenColor)) * ((((fma(_1714, _1710, half(2.0)) * pow(max(fma(half(-float(_1492)), _1492, half(1.0)), half(0.0)), half(0.5) * (_1714 * _1710))) * half(0.15915493667125701904296875)) * (_1488 * (_1714 * _1721))) * _1399)) * _1038), half3(float3(65504.0)));
    float3 _1785 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1788 = dot(_1785, _1785);
    float3 _1793 = _1785 * rsqrt(fast::max(_1788, 9.9999999392252902907785028219223e-09));
    float _1797 = _1788 * float(frame.punctualLights[0].positionFalloff.w);
    float _1802 = fast::clamp(fma(-_1797, _1797, 1.0), 0.0, 1.0);
    float _1821 = fast::clamp(fma(dot(-_1793, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1832 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1802) * half(_1802)) / fast::max(_1788, 9.9999997473787516355514526367188e-05)) * half(_1821)) * half(_1821)), float3(65504.0));
    float3 _1957 = fast::normalize(_983 + _1793);
    half _1889 = clamp(dot(_977, half3(_1793)), half(0.0), half(1.0));
    half _1893 = clamp(dot(_977, half3(_1957)), half(0.0), half(1.0));
    half4 _2022 = half4(cross(_977, half3(_1957)), half(params.facet_alpha) * _1893) * half(64.0);
    half _2003 = _1596 / dot(_2022, _2022);
    half _2067 = half(1.0) - clamp(dot(half3(_1793), half3(_1957)), half(0.0), half(1.0));
    half _2070 = _2067 * _2067;
    half _2111 = half(8192.0) * fma(half(-float(_1889)), _1279, _1889 + _1279);
    half _2115 = half(1.0) / (half(params.facet_sheenAlpha) * _2111);
    half3 _1938 = min(fma(fma((half3(float3(params.facet_f0)) + (_1677 * ((_2070 * _2070) * _2067))) * min(min((_2003 * _2003) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1889, _1642, _1279 * sqrt(fma(_1889 * _1889, _1638, _1632))), half(65504.0)), half(65504.0)), _1337, _1529), (half3(_1832) * _1889) * _1394, (half3(float3(params.facet_sheenColor)) * ((((fma(_2115, _2111, half(2.0)) * pow(max(fma(half(-float(_1893)), _1893, half(1.0)), half(0.0)), half(0.5) * (_2115 * _2111))) * half(0.15915493667125701904296875)) * (_1889 * (_2115 * _1721))) * _1399)) * half3(_1832)), half3(float3(65504.0)));
    float3 _2186 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2189 = dot(_2186, _2186);
    float3 _2194 = _2186 * rsqrt(fast::max(_2189, 9.9999999392252902907785028219223e-09));
    float _2198 = _2189 * float(frame.punctualLights[1].positionFalloff.w);
    float _2203 = fast::clamp(fma(-_2198, _2198, 1.0), 0.0, 1.0);
    float _2222 = fast::clamp(fma(dot(-_2194, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2233 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2203) * half(_2203)) / fast::max(_2189, 9.9999997473787516355514526367188e-05)) * half(_2222)) * half(_2222)), float3(65504.0));
    float3 _2358 = fast::normalize(_983 + _2194);
    half _2290 = clamp(dot(_977, half3(_2194)), half(0.0), half(1.0));
    half _2294 = clamp(dot(_977, half3(_2358)), half(0.0), half(1.0));
    half4 _2423 = half4(cross(_977, half3(_2358)), half(params.facet_alpha) * _2294) * half(64.0);
    half _2404 = _1596 / dot(_2423, _2423);
    half _2468 = half(1.0) - clamp(dot(half3(_2194), half3(_2358)), half(0.0), half(1.0));
    half _2471 = _2468 * _2468;
    half _2512 = half(8192.0) * fma(half(-float(_2290)), _1279, _2290 + _1279);
    half _2516 = half(1.0) / (half(params.facet_sheenAlpha) * _2512);
    half3 _2339 = min(fma(fma((half3(float3(params.facet_f0)) + (_1677 * ((_2471 * _2471) * _2468))) * min(min((_2404 * _2404) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2290, _1642, _1279 * sqrt(fma(_2290 * _2290, _1638, _1632))), half(65504.0)), half(65504.0)), _1337, _1529), (half3(_2233) * _2290) * _1394, (half3(float3(params.facet_sheenColor)) * ((((fma(_2516, _2512, half(2.0)) * pow(max(fma(half(-float(_2294)), _2294, half(1.0)), half(0.0)), half(0.5) * (_2516 * _2512))) * half(0.15915493667125701904296875)) * (_2290 * (_2516 * _1721))) * _1399)) * half3(_2233)), half3(float3(65504.0)));
    out.fragColor = float4(half4(((fma(half4(_1408).xyz, half3(float3(params.facet_sheenColor)) * _1392, fma(half3(float3(params.facet_diffuseColor)), _1229, half4(_1347).xyz * (mix(half4(_1318).xxx, half4(_1318).yyy, half3(float3(params.facet_f0))) * _1337)) * _1394) + _1537) + _1938) + _2339, half(1.0)));
    return out;
}

