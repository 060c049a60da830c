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
    float3 v_worldPosition [[user(locn0)]];
    float3 v_normal [[user(locn1)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _972 = normalize(half3(in.v_normal));
    float3 _978 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1282 = max(dot(_972, half3(_978)), half(9.9999997473787516355514526367188e-05));
    half3 _1286 = reflect(-half3(_978), _972);
    float4 _1321 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1282, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1340 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1321).y) - half(1.0)));
    float4 _1350 = facet_environment.sample(facet_environmentSmplr, float3(_1286), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1398 = half(1.0) - _1282;
    half _1401 = _1398 * _1398;
    half _1408 = fma(half(0.959999978542327880859375), (_1401 * _1401) * _1398, half(0.039999999105930328369140625));
    half _1413 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1380 = fma(half(-float(_1408)), _1413, half(1.0));
    half _1418 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1428 = facet_environment.sample(facet_environmentSmplr, float3(_1286), level(_1418 * (half(4.0) * (half(2.0) - _1418))));
    float3 _1553 = fast::normalize(_978 + frame.lightDirection.xyz);
    half _1486 = clamp(dot(_972, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1490 = clamp(dot(_972, half3(_1553)), half(0.0), half(1.0));
    half _1494 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1553)), half(0.0), half(1.0));
    half _1593 = half(4096.0) * half(params.facet_alpha);
    half3 _1610 = cross(_972, half3(_1553));
    half _1614 = _1610.x;
    half4 _1618 = half4(_1614, _1610.yz, half(params.facet_alpha) * _1490) * half(64.0);
    half _1599 = _1593 / dot(_1618, _1618);
    half _1629 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1635 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1639 = sqrt(fma(_1282 * _1282, _1635, _1629));
    half _1663 = half(1.0) - _1494;
    half _1666 = _1663 * _1663;
    half _1671 = (_1666 * _1666) * _1663;
    half3 _1674 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1512 = half4(frame.lightColor).xyz * _1486;
    half _1710 = _1418 * _1418;
    half4 _1763 = half4(_1614, _1610.yz, _1710 * _1490) * half(64.0);
    half _1720 = half(12.56637096405029296875) * max(_1494 * _1494, half(6.103515625e-05));
    half _1722 = half(4096.0) * _1710;
    half _1726 = _1722 / (dot(_1763, _1763) * _1720);
    float3 _1842 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1845 = dot(_1842, _1842);
    float3 _1850 = _1842 * rsqrt(fast::max(_1845, 9.9999999392252902907785028219223e-09));
    float _1854 = _1845 * float(frame.punctualLights[0].positionFalloff.w);
    float _1859 = fast::clamp(fma(-_1854, _1854, 1.0), 0.0, 1.0);
    float _1878 = fast::clamp(fma(dot(-_1850, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2014 = fast::normalize(_978 + _1850);
    half _1947 = clamp(dot(_972, half3(_1850)), half(0.0), half(1.0));
    half _1951 = clamp(dot(_972, half3(_2014)), half(0.0), half(1.0));
    half _1955 = clamp(dot(half3(_1850), half3(_2014)), half(0.0), half(1.0));
    half3 _2071 = cross(_972, half3(_2014));
    half _2075 = _2071.x;
    half4 _2079 = half4(_2075, _2071.yz, half(params.facet_alpha) * _1951) * half(64.0);
    half _2060 = _1593 / dot(_2079, _2079);
    half _2124 = half(1.0) - _1955;
    half _2127 = _2124 * _2124;
    half _2132 = (_2127 * _2127) * _2124;
    half3 _1973 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1859) * half(_1859)) / fast::max(_1845, 9.9999997473787516355514526367188e-05)) * half(_1878)) * half(_1878)), float3(65504.0))) * _1947;
    half4 _2224 = half4(_2075, _2071.yz, _1710 * _1951) * half(64.0);
    half _2181 = half(12.56637096405029296875) * max(_1955 * _1955, half(6.103515625e-05));
    half _2187 = _1722 / (dot(_2224, _2224) * _2181);
    half3 _2267 = (mix(half4(_1350).xyz * (mix(half4(_1321).xxx, half4(_1321).yyy, half3(float3(params.facet_f0))) * _1340), half4(_1428).xyz, half3(_1408 * _1413)) + min(fma(((half3(float3(params.facet_f0)) + (_1674 * _1671)) * min(min((_1599 * _1599) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1486, _1639, _1282 * sqrt(fma(_1486 * _1486, _1635, _1629))), half(65504.0)), half(65504.0))) * _1340, _1512 * _1380, _1512 * (min(_1726 * (_1726 * _1720), half(65504.0)) * (fma(half(0.959999978542327880859375), _1671, half(0.039999999105930328369140625)) * _1413))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1674 * _2132)) * min(min((_2060 * _2060) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1947, _1639, _1282 * sqrt(fma(_1947 * _1947, _1635, _1629))), half(65504.0)), half(65504.0))) * _1340, _1973 * _1380, _1973 * (min(_2187 * (_2187 * _2181), half(65504.0)) * (fma(half(0.959999978542327880859375), _2132, half(0.039999999105930328369140625)) * _1413))), half3(float3(65504.0)));
    float3 _2303 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2306 = dot(_2303, _2303);
    float3 _2311 = _2303 * rsqrt(fast::max(_2306, 9.9999999392252902907785028219223e-09));
    float _2315 = _2306 * float(frame.punctualLights[1].positionFalloff.w);
    float _2320 = fast::clamp(fma(-_2315, _2315, 1.0), 0.0, 1.0);
    float _2339 = fast::clamp(fma(dot(-_2311, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2475 = fast::normalize(_978 + _2311);
    half _2408 = clamp(dot(_972, half3(_2311)), half(0.0), half(1.0));
    half _2412 = clamp(dot(_972, half3(_2475)), half(0.0), half(1.0));
    half _2416 = clamp(dot(half3(_2311), half3(_2475)), half(0.0), half(1.0));
    half3 _2532 = cross(_972, half3(_2475));
    half _2536 = _2532.x;
    half4 _2540 = half4(_2536, _2532.yz, half(params.facet_alpha) * _2412) * half(64.0);
    half _2521 = _1593 / dot(_2540, _2540);
    half _2585 = half(1.0) - _2416;
    half _2588 = _2585 * _2585;
    half _2593 = (_2588 * _2588) * _2585;
    half3 _2434 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2320) * half(_2320)) / fast::max(_2306, 9.9999997473787516355514526367188e-05)) * half(_2339)) * half(_2339)), float3(65504.0))) * _2408;
    half4 _2685 = half4(_2536, _2532.yz, _1710 * _2412) * half(64.0);
    half _2642 = half(12.56637096405029296875) * max(_2416 * _2416, half(6.103515625e-05));
    half _2648 = _1722 / (dot(_2685, _2685) * _2642);
    out.fragColor = float4(half4(_2267 + min(fma(((half3(float3(params.facet_f0)) + (_1674 * _2593)) * min(min((_2521 * _2521) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2408, _1639, _1282 * sqrt(fma(_2408 * _2408, _1635, _1629))), half(65504.0)), half(65504.0))) * _1340, _2434 * _1380, _2434 * (min(_2648 * (_2648 * _2642), half(65504.0)) * (fma(half(0.959999978542327880859375), _2593, half(0.039999999105930328369140625)) * _1413))), half3(float3(65504.0))), half(1.0)));
    return out;
}

