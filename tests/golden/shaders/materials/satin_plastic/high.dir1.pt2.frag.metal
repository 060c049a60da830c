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
    half3 _968 = normalize(half3(in.v_normal));
    float3 _974 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1141 = _968.y;
    half _1146 = _968.z;
    half _1151 = _968.x;
    half3 _1219 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1141)) + (half4(frame.sh[2]).xyz * _1146)) + (half4(frame.sh[3]).xyz * _1151)) + (((((half4(frame.sh[4]).xyz * (_1151 * _1141)) + (half4(frame.sh[5]).xyz * (_1141 * _1146))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1146, _1146, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1151 * _1146))) + (half4(frame.sh[8]).xyz * fma(_1151, _1151, half(-float(_1141 * _1141))))), half3(float3(0.0)));
    half _1269 = max(dot(_968, half3(_974)), half(9.9999997473787516355514526367188e-05));
    half3 _1273 = reflect(-half3(_974), _968);
    float4 _1308 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1269, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1327 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1308).y) - half(1.0)));
    float4 _1339 = facet_environment.sample(facet_environmentSmplr, float3(_1273), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1416 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1373 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1269, _1416)), level(0.0));
    half3 _1423 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2741 = half4(_1373);
    half _1386 = _2741.z;
    half _1388 = fma(half(-float(max(_1423.x, max(_1423.y, _1423.z)))), _1386, half(1.0));
    half _1432 = _1416 * _1416;
    half4 _2745 = half4(_1373);
    half _1393 = _2745.w;
    float4 _1449 = facet_environment.sample(facet_environmentSmplr, float3(_1273), level(_1416 * (half(4.0) * (half(2.0) - _1416))));
    half3 _1029 = half4(frame.lightColor).xyz;
    float3 _1574 = fast::normalize(_974 + frame.lightDirection.xyz);
    half _1506 = clamp(dot(_968, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1510 = clamp(dot(_968, half3(_1574)), half(0.0), half(1.0));
    half3 _1614 = cross(_968, half3(_1574));
    half _1617 = _1510 * half(params.facet_alpha);
    half _1626 = half(params.facet_alpha) / fma(_1617, _1617, dot(_1614, _1614));
    half _1640 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1646 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1650 = sqrt(fma(_1269 * _1269, _1646, _1640));
    half _1674 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1574)), half(0.0), half(1.0));
    half _1677 = _1674 * _1674;
    half3 _1685 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1718 = half(8192.0) * fma(half(-float(_1506)), _1269, _1506 + _1269);
    half _1722 = half(1.0) / (_1432 * _1718);
    half _1729 = half(2048.0) * _1432;
    half3 _1547 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    half3 _1555 = min(fma(fma((half3(float3(params.facet_f0)) + (_1685 * ((_1677 * _1677) * _1674))) * min(min((_1626 * _1626) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1506, _1650, _1269 * sqrt(fma(_1506 * _1506, _1646, _1640))), half(65504.0)), half(65504.0)), _1327, _1547), (_1029 * _1506) * _1388, (_1423 * ((((fma(_1722, _1718, half(2.0)) * pow(max(fma(half(-float(_1510)), _1510, half(1.0)), half(0.0)), half(0.5) * (_1722 * _1718))) * half(0.15915493667125701904296875)) * (_1506 * (_1722 * _1729))) * _1393)) * _1029), half3(float3(65504.0)));
    float3 _1793 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1796 = dot(_1793, _1793);
    float3 _1801 = _1793 * rsqrt(fast::max(_1796, 9.9999999392252902907785028219223e-09));
    float _1805 = _1796 * float(frame.punctualLights[0].positionFalloff.w);
    float _1810 = fast::clamp(fma(-_1805, _1805, 1.0), 0.0, 1.0);
    float _1829 = fast::clamp(fma(dot(-_1801, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1840 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1810) * half(_1810)) / fast::max(_1796, 9.9999997473787516355514526367188e-05)) * half(_1829)) * half(_1829)), float3(65504.0));
    float3 _1965 = fast::normalize(_974 + _1801);
    half _1897 = clamp(dot(_968, half3(_1801)), half(0.0), half(1.0));
    half _1901 = clamp(dot(_968, half3(_1965)), half(0.0), half(1.0));
    half3 _2005 = cross(_968, half3(_1965));
    half _2008 = _1901 * half(params.facet_alpha);
    half _2017 = half(params.facet_alpha) / fma(_2008, _2008, dot(_2005, _2005));
    half _2065 = half(1.0) - clamp(dot(half3(_1801), half3(_1965)), half(0.0), half(1.0));
    half _2068 = _2065 * _2065;
    half _2109 = half(8192.0) * fma(half(-float(_1897)), _1269, _1897 + _1269);
    half _2113 = half(1.0) / (_1432 * _2109);
    half3 _1946 = min(fma(fma((half3(float3(params.facet_f0)) + (_1685 * ((_2068 * _2068) * _2065))) * min(min((_2017 * _2017) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1897, _1650, _1269 * sqrt(fma(_1897 * _1897, _1646, _1640))), half(65504.0)), half(65504.0)), _1327, _1547), (half3(_1840) * _1897) * _1388, (_1423 * ((((fma(_2113, _2109, half(2.0)) * pow(max(fma(half(-float(_1901)), _1901, half(1.0)), half(0.0)), half(0.5) * (_2113 * _2109))) * half(0.15915493667125701904296875)) * (_1897 * (_2113 * _1729))) * _1393)) * half3(_1840)), half3(float3(65504.0)));
    float3 _2184 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2187 = dot(_2184, _2184);
    float3 _2192 = _2184 * rsqrt(fast::max(_2187, 9.9999999392252902907785028219223e-09));
    float _2196 = _2187 * float(frame.punctualLights[1].positionFalloff.w);
    float _2201 = fast::clamp(fma(-_2196, _2196, 1.0), 0.0, 1.0);
    float _2220 = fast::clamp(fma(dot(-_2192, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2231 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2201) * half(_2201)) / fast::max(_2187, 9.9999997473787516355514526367188e-05)) * half(_2220)) * half(_2220)), float3(65504.0));
    float3 _2356 = fast::normalize(_974 + _2192);
    half _2288 = clamp(dot(_968, half3(_2192)), half(0.0), half(1.0));
    half _2292 = clamp(dot(_968, half3(_2356)), half(0.0), half(1.0));
    half3 _2396 = cross(_968, half3(_2356));
    half _2399 = _2292 * half(params.facet_alpha);
    half _2408 = half(params.facet_alpha) / fma(_2399, _2399, dot(_2396, _2396));
    half _2456 = half(1.0) - clamp(dot(half3(_2192), half3(_2356)), half(0.0), half(1.0));
    half _2459 = _2456 * _2456;
    half _2500 = half(8192.0) * fma(half(-float(_2288)), _1269, _2288 + _1269);
    half _2504 = half(1.0) / (_1432 * _2500);
    half3 _2337 = min(fma(fma((half3(float3(params.facet_f0)) + (_1685 * ((_2459 * _2459) * _2456))) * min(min((_2408 * _2408) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2288, _1650, _1269 * sqrt(fma(_2288 * _2288, _1646, _1640))), half(65504.0)), half(65504.0)), _1327, _1547), (half3(_2231) * _2288) * _1388, (_1423 * ((((fma(_2504, _2500, half(2.0)) * pow(max(fma(half(-float(_2292)), _2292, half(1.0)), half(0.0)), half(0.5) * (_2504 * _2500))) * half(0.15915493667125701904296875)) * (_2288 * (_2504 * _1729))) * _1393)) * half3(_2231)), half3(float3(65504.0)));
    out.fragColor = float4(half4(((fma(half4(_1449).xyz, _1423 * _1386, fma(half3(float3(params.facet_diffuseColor)), _1219, half4(_1339).xyz * (mix(half4(_1308).xxx, half4(_1308).yyy, half3(float3(params.facet_f0))) * _1327)) * _1388) + _1555) + _1946) + _2337, half(1.0)));
    return out;
}

