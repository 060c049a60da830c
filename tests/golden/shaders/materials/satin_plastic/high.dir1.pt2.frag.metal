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
    half3 _966 = normalize(half3(in.v_normal));
    float3 _972 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1139 = _966.y;
    half _1144 = _966.z;
    half _1149 = _966.x;
    half3 _1217 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1139)) + (half4(frame.sh[2]).xyz * _1144)) + (half4(frame.sh[3]).xyz * _1149)) + (((((half4(frame.sh[4]).xyz * (_1149 * _1139)) + (half4(frame.sh[5]).xyz * (_1139 * _1144))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1144, _1144, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1149 * _1144))) + (half4(frame.sh[8]).xyz * fma(_1149, _1149, half(-float(_1139 * _1139))))), half3(float3(0.0)));
    half _1267 = max(dot(_966, half3(_972)), half(9.9999997473787516355514526367188e-05));
    half3 _1271 = reflect(-half3(_972), _966);
    float4 _1306 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1267, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1325 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1306).y) - half(1.0)));
    float4 _1335 = facet_environment.sample(facet_environmentSmplr, float3(_1271), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1412 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1369 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1267, _1412)), level(0.0));
    half3 _1419 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2735 = half4(_1369);
    half _1382 = _2735.z;
    half _1384 = fma(half(-float(max(_1419.x, max(_1419.y, _1419.z)))), _1382, half(1.0));
    half _1428 = _1412 * _1412;
    half4 _2739 = half4(_1369);
    half _1389 = _2739.w;
    float4 _1443 = facet_environment.sample(facet_environmentSmplr, float3(_1271), level(_1412 * (half(4.0) * (half(2.0) - _1412))));
    half3 _1027 = half4(frame.lightColor).xyz;
    float3 _1568 = fast::normalize(_972 + frame.lightDirection.xyz);
    half _1500 = clamp(dot(_966, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1504 = clamp(dot(_966, half3(_1568)), half(0.0), half(1.0));
    half3 _1608 = cross(_966, half3(_1568));
    half _1611 = _1504 * half(params.facet_alpha);
    half _1620 = half(params.facet_alpha) / fma(_1611, _1611, dot(_1608, _1608));
    half _1634 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1640 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1644 = sqrt(fma(_1267 * _1267, _1640, _1634));
    half _1668 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1568)), half(0.0), half(1.0));
    half _1671 = _1668 * _1668;
    half3 _1679 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1712 = half(8192.0) * fma(half(-float(_1500)), _1267, _1500 + _1267);
    half _1716 = half(1.0) / (_1428 * _1712);
    half _1723 = half(2048.0) * _1428;
    half3 _1541 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    half3 _1549 = min(fma(fma((half3(float3(params.facet_f0)) + (_1679 * ((_1671 * _1671) * _1668))) * min(min((_1620 * _1620) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1500, _1644, _1267 * sqrt(fma(_1500 * _1500, _1640, _1634))), half(65504.0)), half(65504.0)), _1325, _1541), (_1027 * _1500) * _1384, (_1419 * ((((fma(_1716, _1712, half(2.0)) * pow(max(fma(half(-float(_1504)), _1504, half(1.0)), half(0.0)), half(0.5) * (_1716 * _1712))) * half(0.15915493667125701904296875)) * (_1500 * (_1716 * _1723))) * _1389)) * _1027), half3(float3(65504.0)));
    float3 _1787 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1790 = dot(_1787, _1787);
    float3 _1795 = _1787 * rsqrt(fast::max(_1790, 9.9999999392252902907785028219223e-09));
    float _1799 = _1790 * float(frame.punctualLights[0].positionFalloff.w);
    float _1804 = fast::clamp(fma(-_1799, _1799, 1.0), 0.0, 1.0);
    float _1823 = fast::clamp(fma(dot(-_1795, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1834 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1804) * half(_1804)) / fast::max(_1790, 9.9999997473787516355514526367188e-05)) * half(_1823)) * half(_1823)), float3(65504.0));
    float3 _1959 = fast::normalize(_972 + _1795);
    half _1891 = clamp(dot(_966, half3(_1795)), half(0.0), half(1.0));
    half _1895 = clamp(dot(_966, half3(_1959)), half(0.0), half(1.0));
    half3 _1999 = cross(_966, half3(_1959));
    half _2002 = _1895 * half(params.facet_alpha);
    half _2011 = half(params.facet_alpha) / fma(_2002, _2002, dot(_1999, _1999));
    half _2059 = half(1.0) - clamp(dot(half3(_1795), half3(_1959)), half(0.0), half(1.0));
    half _2062 = _2059 * _2059;
    half _2103 = half(8192.0) * fma(half(-float(_1891)), _1267, _1891 + _1267);
    half _2107 = half(1.0) / (_1428 * _2103);
    half3 _1940 = min(fma(fma((half3(float3(params.facet_f0)) + (_1679 * ((_2062 * _2062) * _2059))) * min(min((_2011 * _2011) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1891, _1644, _1267 * sqrt(fma(_1891 * _1891, _1640, _1634))), half(65504.0)), half(65504.0)), _1325, _1541), (half3(_1834) * _1891) * _1384, (_1419 * ((((fma(_2107, _2103, half(2.0)) * pow(max(fma(half(-float(_1895)), _1895, half(1.0)), half(0.0)), half(0.5) * (_2107 * _2103))) * half(0.15915493667125701904296875)) * (_1891 * (_2107 * _1723))) * _1389)) * half3(_1834)), half3(float3(65504.0)));
    float3 _2178 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2181 = dot(_2178, _2178);
    float3 _2186 = _2178 * rsqrt(fast::max(_2181, 9.9999999392252902907785028219223e-09));
    float _2190 = _2181 * float(frame.punctualLights[1].positionFalloff.w);
    float _2195 = fast::clamp(fma(-_2190, _2190, 1.0), 0.0, 1.0);
    float _2214 = fast::clamp(fma(dot(-_2186, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2225 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2195) * half(_2195)) / fast::max(_2181, 9.9999997473787516355514526367188e-05)) * half(_2214)) * half(_2214)), float3(65504.0));
    float3 _2350 = fast::normalize(_972 + _2186);
    half _2282 = clamp(dot(_966, half3(_2186)), half(0.0), half(1.0));
    half _2286 = clamp(dot(_966, half3(_2350)), half(0.0), half(1.0));
    half3 _2390 = cross(_966, half3(_2350));
    half _2393 = _2286 * half(params.facet_alpha);
    half _2402 = half(params.facet_alpha) / fma(_2393, _2393, dot(_2390, _2390));
    half _2450 = half(1.0) - clamp(dot(half3(_2186), half3(_2350)), half(0.0), half(1.0));
    half _2453 = _2450 * _2450;
    half _2494 = half(8192.0) * fma(half(-float(_2282)), _1267, _2282 + _1267);
    half _2498 = half(1.0) / (_1428 * _2494);
    half3 _2331 = min(fma(fma((half3(float3(params.facet_f0)) + (_1679 * ((_2453 * _2453) * _2450))) * min(min((_2402 * _2402) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2282, _1644, _1267 * sqrt(fma(_2282 * _2282, _1640, _1634))), half(65504.0)), half(65504.0)), _1325, _1541), (half3(_2225) * _2282) * _1384, (_1419 * ((((fma(_2498, _2494, half(2.0)) * pow(max(fma(half(-float(_2286)), _2286, half(1.0)), half(0.0)), half(0.5) * (_2498 * _2494))) * half(0.15915493667125701904296875)) * (_2282 * (_2498 * _1723))) * _1389)) * half3(_2225)), half3(float3(65504.0)));
    out.fragColor = float4(half4(((fma(half4(_1443).xyz, _1419 * _1382, fma(half3(float3(params.facet_diffuseColor)), _1217, half4(_1335).xyz * (mix(half4(_1306).xxx, half4(_1306).yyy, half3(float3(params.facet_f0))) * _1325)) * _1384) + _1549) + _1940) + _2331, half(1.0)));
    return out;
}

