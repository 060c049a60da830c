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
    half _1158 = _985.y;
    half _1163 = _985.z;
    half _1168 = _985.x;
    half3 _1236 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1158)) + (half4(frame.sh[2]).xyz * _1163)) + (half4(frame.sh[3]).xyz * _1168)) + (((((half4(frame.sh[4]).xyz * (_1168 * _1158)) + (half4(frame.sh[5]).xyz * (_1158 * _1163))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1163, _1163, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1168 * _1163))) + (half4(frame.sh[8]).xyz * fma(_1168, _1168, half(-float(_1158 * _1158))))), half3(float3(0.0)));
    half _1286 = max(dot(_985, half3(_991)), half(9.9999997473787516355514526367188e-05));
    half3 _1290 = reflect(-half3(_991), _985);
    float4 _1325 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1286, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1344 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1325).y) - half(1.0)));
    float4 _1351 = facet_environment.sample(facet_environmentSmplr, float3(_1290), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1428 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1385 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1286, _1428)), level(0.0));
    half3 _1435 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2788 = half4(_1385);
    half _1398 = _2788.z;
    half _1400 = fma(half(-float(max(_1435.x, max(_1435.y, _1435.z)))), _1398, half(1.0));
    half _1444 = _1428 * _1428;
    half4 _2792 = half4(_1385);
    half _1405 = _2792.w;
    float4 _1456 = facet_environment.sample(facet_environmentSmplr, float3(_1290), level(_1428 * half(4.0)));
    half3 _1046 = half4(frame.lightColor).xyz;
    float3 _1581 = fast::normalize(_991 + frame.lightDirection.xyz);
    half _1513 = clamp(dot(_985, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1517 = clamp(dot(_985, half3(_1581)), half(0.0), half(1.0));
    half _1622 = half(4096.0) * half(params.facet_alpha);
    half3 _1642 = cross(_985, half3(_1581)) * half(64.0);
    half _1645 = half(64.0) * half(params.facet_alpha);
    half _1646 = _1517 * _1645;
    half _1628 = _1622 / fma(_1646, _1646, dot(_1642, _1642));
    half _1661 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1667 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1671 = sqrt(fma(_1286 * _1286, _1667, _1661));
    half _1695 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1581)), half(0.0), half(1.0));
    half _1698 = _1695 * _1695;
    half3 _1706 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1739 = half(8192.0) * fma(half(-float(_1513)), _1286, _1513 + _1286);
    half _1743 = half(1.0) / (_1444 * _1739);
    half _1750 = half(2048.0) * _1444;
    half3 _1554 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    half3 _1562 = min(fma(fma((half3(float3(params.facet_f0)) + (_1706 * ((_1698 * _1698) * _1695))) * min(min((_1628 * _1628) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1513, _1671, _1286 * sqrt(fma(_1513 * _1513, _1667, _1661))), half(65504.0)), half(65504.0)), _1344, _1554), (_1046 * _1513) * _1400, (_1435 * ((((fma(_1743, _1739, half(2.0)) * pow(max(fma(half(-float(_1517)), _1517, half(1.0)), half(0.0)), half(0.5) * (_1743 * _1739))) * half(0.15915493667125701904296875)) * (_1513 * (_1743 * _1750))) * _1405)) * _1046), half3(float3(65504.0)));
    float3 _1814 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1817 = dot(_1814, _1814);
    float3 _1822 = _1814 * rsqrt(fast::max(_1817, 9.9999999392252902907785028219223e-09));
    float _1826 = _1817 * float(frame.punctualLights[0].positionFalloff.w);
    float _1831 = fast::clamp(fma(-_1826, _1826, 1.0), 0.0, 1.0);
    float _1850 = fast::clamp(fma(dot(-_1822, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1861 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1831) * half(_1831)) / fast::max(_1817, 9.9999997473787516355514526367188e-05)) * half(_1850)) * half(_1850)), float3(65504.0));
    float3 _1986 = fast::normalize(_991 + _1822);
    half _1918 = clamp(dot(_985, half3(_1822)), half(0.0), half(1.0));
    half _1922 = clamp(dot(_985, half3(_1986)), half(0.0), half(1.0));
    half3 _2047 = cross(_985, half3(_1986)) * half(64.0);
    half _2051 = _1922 * _1645;
    half _2033 = _1622 / fma(_2051, _2051, dot(_2047, _2047));
    half _2100 = half(1.0) - clamp(dot(half3(_1822), half3(_1986)), half(0.0), half(1.0));
    half _2103 = _2100 * _2100;
    half _2144 = half(8192.0) * fma(half(-float(_1918)), _1286, _1918 + _1286);
    half _2148 = half(1.0) / (_1444 * _2144);
    half3 _1967 = min(fma(fma((half3(float3(params.facet_f0)) + (_1706 * ((_2103 * _2103) * _2100))) * min(min((_2033 * _2033) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1918, _1671, _1286 * sqrt(fma(_1918 * _1918, _1667, _1661))), half(65504.0)), half(65504.0)), _1344, _1554), (half3(_1861) * _1918) * _1400, (_1435 * ((((fma(_2148, _2144, half(2.0)) * pow(max(fma(half(-float(_1922)), _1922, half(1.0)), half(0.0)), half(0.5) * (_2148 * _2144))) * half(0.15915493667125701904296875)) * (_1918 * (_2148 * _1750))) * _1405)) * half3(_1861)), half3(float3(65504.0)));
    float3 _2219 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2222 = dot(_2219, _2219);
    float3 _2227 = _2219 * rsqrt(fast::max(_2222, 9.9999999392252902907785028219223e-09));
    float _2231 = _2222 * float(frame.punctualLights[1].positionFalloff.w);
    float _2236 = fast::clamp(fma(-_2231, _2231, 1.0), 0.0, 1.0);
    float _2255 = fast::clamp(fma(dot(-_2227, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2266 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2236) * half(_2236)) / fast::max(_2222, 9.9999997473787516355514526367188e-05)) * half(_2255)) * half(_2255)), float3(65504.0));
    float3 _2391 = fast::normalize(_991 + _2227);
    half _2323 = clamp(dot(_985, half3(_2227)), half(0.0), half(1.0));
    half _2327 = clamp(dot(_985, half3(_2391)), half(0.0), half(1.0));
    half3 _2452 = cross(_985, half3(_2391)) * half(64.0);
    half _2456 = _2327 * _1645;
    half _2438 = _1622 / fma(_2456, _2456, dot(_2452, _2452));
    half _2505 = half(1.0) - clamp(dot(half3(_2227), half3(_2391)), half(0.0), half(1.0));
    half _2508 = _2505 * _2505;
    half _2549 = half(8192.0) * fma(half(-float(_2323)), _1286, _2323 + _1286);
    half _2553 = half(1.0) / (_1444 * _2549);
    half3 _2372 = min(fma(fma((half3(float3(params.facet_f0)) + (_1706 * ((_2508 * _2508) * _2505))) * min(min((_2438 * _2438) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2323, _1671, _1286 * sqrt(fma(_2323 * _2323, _1667, _1661))), half(65504.0)), half(65504.0)), _1344, _1554), (half3(_2266) * _2323) * _1400, (_1435 * ((((fma(_2553, _2549, half(2.0)) * pow(max(fma(half(-float(_2327)), _2327, half(1.0)), half(0.0)), half(0.5) * (_2553 * _2549))) * half(0.15915493667125701904296875)) * (_2323 * (_2553 * _1750))) * _1405)) * half3(_2266)), half3(float3(65504.0)));
    out.fragColor = float4(half4(((fma(half4(_1456).xyz, _1435 * _1398, fma(half3(float3(params.facet_diffuseColor)), _1236, half4(_1351).xyz * (mix(half4(_1325).xxx, half4(_1325).yyy, half3(float3(params.facet_f0))) * _1344)) * _1400) + _1562) + _1967) + _2372, half(1.0)));
    return out;
}

