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
    half _1130 = _977.y;
    half _1135 = _977.z;
    half _1140 = _977.x;
    half3 _1208 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1130)) + (half4(frame.sh[2]).xyz * _1135)) + (half4(frame.sh[3]).xyz * _1140)) + (((((half4(frame.sh[4]).xyz * (_1140 * _1130)) + (half4(frame.sh[5]).xyz * (_1130 * _1135))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1135, _1135, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1140 * _1135))) + (half4(frame.sh[8]).xyz * fma(_1140, _1140, half(-float(_1130 * _1130))))), half3(float3(0.0)));
    half _1258 = max(dot(_977, half3(_983)), half(9.9999997473787516355514526367188e-05));
    half3 _1262 = reflect(-half3(_983), _977);
    float4 _1297 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1258, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1316 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1297).y) - half(1.0)));
    float4 _1326 = facet_environment.sample(facet_environmentSmplr, float3(_1262), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float4 _1358 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1258, half(params.facet_sheenRoughness))), level(0.0));
    half4 _2405 = half4(_1358);
    half _1371 = _2405.z;
    half _1373 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _1371, half(1.0));
    half4 _2409 = half4(_1358);
    half _1378 = _2409.w;
    float4 _1387 = facet_environment.sample(facet_environmentSmplr, float3(_1262), level(params.facet_sheenLod));
    float3 _1447 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1450 = dot(_1447, _1447);
    float3 _1455 = _1447 * rsqrt(fast::max(_1450, 9.9999999392252902907785028219223e-09));
    float _1459 = _1450 * float(frame.punctualLights[0].positionFalloff.w);
    float _1464 = fast::clamp(fma(-_1459, _1459, 1.0), 0.0, 1.0);
    float _1483 = fast::clamp(fma(dot(-_1455, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1494 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1464) * half(_1464)) / fast::max(_1450, 9.9999997473787516355514526367188e-05)) * half(_1483)) * half(_1483)), float3(65504.0));
    float3 _1619 = fast::normalize(_983 + _1455);
    half _1551 = clamp(dot(_977, half3(_1455)), half(0.0), half(1.0));
    half _1555 = clamp(dot(_977, half3(_1619)), half(0.0), half(1.0));
    half _1659 = half(4096.0) * half(params.facet_alpha);
    half4 _1684 = half4(cross(_977, half3(_1619)), half(params.facet_alpha) * _1555) * half(64.0);
    half _1665 = _1659 / dot(_1684, _1684);
    half _1695 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1701 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1705 = sqrt(fma(_1258 * _1258, _1701, _1695));
    half _1729 = half(1.0) - clamp(dot(half3(_1455), half3(_1619)), half(0.0), half(1.0));
    half _1732 = _1729 * _1729;
    half3 _1740 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1773 = half(8192.0) * fma(half(-float(_1551)), _1258, _1551 + _1258);
    half _1777 = half(1.0) / (half(params.facet_sheenAlpha) * _1773);
    half _1784 = half(2048.0) * half(params.facet_sheenAlpha);
    half3 _1592 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    half3 _1600 = min(fma(fma((half3(float3(params.facet_f0)) + (_1740 * ((_1732 * _1732) * _1729))) * min(min((_1665 * _1665) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1551, _1705, _1258 * sqrt(fma(_1551 * _1551, _1701, _1695))), half(65504.0)), half(65504.0)), _1316, _1592), (half3(_1494) * _1551) * _1373, (half3(float3(params.facet_sheenColor)) * ((((fma(_1777, _1773, half(2.0)) * pow(max(fma(half(-float(_1555)), _1555, half(1.0)), half(0.0)), half(0.5) * (_1777 * _1773))) * half(0.15915493667125701904296875)) * (_1551 * (_1777 * _1784))) * _1378)) * half3(_1494)), half3(float3(65504.0)));
    float3 _1848 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1851 = dot(_1848, _1848);
    float3 _1856 = _1848 * rsqrt(fast::max(_1851, 9.9999999392252902907785028219223e-09));
    float _1860 = _1851 * float(frame.punctualLights[1].positionFalloff.w);
    float _1865 = fast::clamp(fma(-_1860, _1860, 1.0), 0.0, 1.0);
    float _1884 = fast::clamp(fma(dot(-_1856, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1895 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1865) * half(_1865)) / fast::max(_1851, 9.9999997473787516355514526367188e-05)) * half(_1884)) * half(_1884)), float3(65504.0));
    float3 _2020 = fast::normalize(_983 + _1856);
    half _1952 = clamp(dot(_977, half3(_1856)), half(0.0), half(1.0));
    half _1956 = clamp(dot(_977, half3(_2020)), half(0.0), half(1.0));
    half4 _2085 = half4(cross(_977, half3(_2020)), half(params.facet_alpha) * _1956) * half(64.0);
    half _2066 = _1659 / dot(_2085, _2085);
    half _2130 = half(1.0) - clamp(dot(half3(_1856), half3(_2020)), half(0.0), half(1.0));
    half _2133 = _2130 * _2130;
    half _2174 = half(8192.0) * fma(half(-float(_1952)), _1258, _1952 + _1258);
    half _2178 = half(1.0) / (half(params.facet_sheenAlpha) * _2174);
    half3 _2001 = min(fma(fma((half3(float3(params.facet_f0)) + (_1740 * ((_2133 * _2133) * _2130))) * min(min((_2066 * _2066) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1952, _1705, _1258 * sqrt(fma(_1952 * _1952, _1701, _1695))), half(65504.0)), half(65504.0)), _1316, _1592), (half3(_1895) * _1952) * _1373, (half3(float3(params.facet_sheenColor)) * ((((fma(_2178, _2174, half(2.0)) * pow(max(fma(half(-float(_1956)), _1956, half(1.0)), half(0.0)), half(0.5) * (_2178 * _2174))) * half(0.15915493667125701904296875)) * (_1952 * (_2178 * _1784))) * _1378)) * half3(_1895)), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_1387).xyz, half3(float3(params.facet_sheenColor)) * _1371, fma(half3(float3(params.facet_diffuseColor)), _1208, half4(_1326).xyz * (mix(half4(_1297).xxx, half4(_1297).yyy, half3(float3(params.facet_f0))) * _1316)) * _1373) + _1600) + _2001, half(1.0)));
    return out;
}

