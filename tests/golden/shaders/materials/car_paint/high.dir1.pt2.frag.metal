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
    float4 _1347 = facet_environment.sample(facet_environmentSmplr, float3(_1286), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1395 = half(1.0) - _1282;
    half _1398 = _1395 * _1395;
    half _1405 = fma(half(0.959999978542327880859375), (_1398 * _1398) * _1395, half(0.039999999105930328369140625));
    half _1410 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1377 = fma(half(-float(_1405)), _1410, half(1.0));
    half _1415 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1422 = facet_environment.sample(facet_environmentSmplr, float3(_1286), level(_1415 * half(4.0)));
    float3 _1547 = fast::normalize(_978 + frame.lightDirection.xyz);
    half _1480 = clamp(dot(_972, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1484 = clamp(dot(_972, half3(_1547)), half(0.0), half(1.0));
    half _1488 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1547)), half(0.0), half(1.0));
    half _1588 = half(4096.0) * half(params.facet_alpha);
    half3 _1608 = cross(_972, half3(_1547)) * half(64.0);
    half _1611 = half(64.0) * half(params.facet_alpha);
    half _1612 = _1484 * _1611;
    half _1615 = dot(_1608, _1608);
    half _1594 = _1588 / fma(_1612, _1612, _1615);
    half _1627 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1633 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1637 = sqrt(fma(_1282 * _1282, _1633, _1627));
    half _1661 = half(1.0) - _1488;
    half _1664 = _1661 * _1661;
    half _1669 = (_1664 * _1664) * _1661;
    half3 _1672 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1506 = half4(frame.lightColor).xyz * _1480;
    half _1708 = _1415 * _1415;
    half _1758 = half(64.0) * _1708;
    half _1759 = _1484 * _1758;
    half _1718 = half(12.56637096405029296875) * max(_1488 * _1488, half(6.103515625e-05));
    half _1720 = half(4096.0) * _1708;
    half _1724 = _1720 / (fma(_1759, _1759, _1615) * _1718);
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
    half3 _2075 = cross(_972, half3(_2014)) * half(64.0);
    half _2079 = _1951 * _1611;
    half _2082 = dot(_2075, _2075);
    half _2061 = _1588 / fma(_2079, _2079, _2082);
    half _2128 = half(1.0) - _1955;
    half _2131 = _2128 * _2128;
    half _2136 = (_2131 * _2131) * _2128;
    half3 _1973 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1859) * half(_1859)) / fast::max(_1845, 9.9999997473787516355514526367188e-05)) * half(_1878)) * half(_1878)), float3(65504.0))) * _1947;
    half _2226 = _1951 * _1758;
    half _2185 = half(12.56637096405029296875) * max(_1955 * _1955, half(6.103515625e-05));
    half _2191 = _1720 / (fma(_2226, _2226, _2082) * _2185);
    half3 _2273 = (mix(half4(_1347).xyz * (mix(half4(_1321).xxx, half4(_1321).yyy, half3(float3(params.facet_f0))) * _1340), half4(_1422).xyz, half3(_1405 * _1410)) + min(fma(((half3(float3(params.facet_f0)) + (_1672 * _1669)) * min(min((_1594 * _1594) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1480, _1637, _1282 * sqrt(fma(_1480 * _1480, _1633, _1627))), half(65504.0)), half(65504.0))) * _1340, _1506 * _1377, _1506 * (min(_1724 * (_1724 * _1718), half(65504.0)) * (fma(half(0.959999978542327880859375), _1669, half(0.039999999105930328369140625)) * _1410))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1672 * _2136)) * min(min((_2061 * _2061) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1947, _1637, _1282 * sqrt(fma(_1947 * _1947, _1633, _1627))), half(65504.0)), half(65504.0))) * _1340, _1973 * _1377, _1973 * (min(_2191 * (_2191 * _2185), half(65504.0)) * (fma(half(0.959999978542327880859375), _2136, half(0.039999999105930328369140625)) * _1410))), half3(float3(65504.0)));
    float3 _2309 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2312 = dot(_2309, _2309);
    float3 _2317 = _2309 * rsqrt(fast::max(_2312, 9.9999999392252902907785028219223e-09));
    float _2321 = _2312 * float(frame.punctualLights[1].positionFalloff.w);
    float _2326 = fast::clamp(fma(-_2321, _2321, 1.0), 0.0, 1.0);
    float _2345 = fast::clamp(fma(dot(-_2317, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2481 = fast::normalize(_978 + _2317);
    half _2414 = clamp(dot(_972, half3(_2317)), half(0.0), half(1.0));
    half _2418 = clamp(dot(_972, half3(_2481)), half(0.0), half(1.0));
    half _2422 = clamp(dot(half3(_2317), half3(_2481)), half(0.0), half(1.0));
    half3 _2542 = cross(_972, half3(_2481)) * half(64.0);
    half _2546 = _2418 * _1611;
    half _2549 = dot(_2542, _2542);
    half _2528 = _1588 / fma(_2546, _2546, _2549);
    half _2595 = half(1.0) - _2422;
    half _2598 = _2595 * _2595;
    half _2603 = (_2598 * _2598) * _2595;
    half3 _2440 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2326) * half(_2326)) / fast::max(_2312, 9.9999997473787516355514526367188e-05)) * half(_2345)) * half(_2345)), float3(65504.0))) * _2414;
    half _2693 = _2418 * _1758;
    half _2652 = half(12.56637096405029296875) * max(_2422 * _2422, half(6.103515625e-05));
    half _2658 = _1720 / (fma(_2693, _2693, _2549) * _2652);
    out.fragColor = float4(half4(_2273 + min(fma(((half3(float3(params.facet_f0)) + (_1672 * _2603)) * min(min((_2528 * _2528) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2414, _1637, _1282 * sqrt(fma(_2414 * _2414, _1633, _1627))), half(65504.0)), half(65504.0))) * _1340, _2440 * _1377, _2440 * (min(_2658 * (_2658 * _2652), half(65504.0)) * (fma(half(0.959999978542327880859375), _2603, half(0.039999999105930328369140625)) * _1410))), half3(float3(65504.0))), half(1.0)));
    return out;
}

