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
    half3 _981 = normalize(half3(in.v_normal));
    float3 _987 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1154 = _981.y;
    half _1159 = _981.z;
    half _1164 = _981.x;
    half3 _1232 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1154)) + (half4(frame.sh[2]).xyz * _1159)) + (half4(frame.sh[3]).xyz * _1164)) + (((((half4(frame.sh[4]).xyz * (_1164 * _1154)) + (half4(frame.sh[5]).xyz * (_1154 * _1159))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1159, _1159, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1164 * _1159))) + (half4(frame.sh[8]).xyz * fma(_1164, _1164, half(-float(_1154 * _1154))))), half3(float3(0.0)));
    half _1282 = max(dot(_981, half3(_987)), half(9.9999997473787516355514526367188e-05));
    half3 _1286 = reflect(-half3(_987), _981);
    float4 _1321 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1282, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1340 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1321).y) - half(1.0)));
    float4 _1347 = facet_environment.sample(facet_environmentSmplr, float3(_1286), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1424 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1381 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1282, _1424)), level(0.0));
    half3 _1431 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2772 = half4(_1381);
    half _1394 = _2772.z;
    half _1396 = fma(half(-float(max(_1431.x, max(_1431.y, _1431.z)))), _1394, half(1.0));
    half _1440 = _1424 * _1424;
    half4 _2776 = half4(_1381);
    half _1401 = _2776.w;
    float4 _1452 = facet_environment.sample(facet_environmentSmplr, float3(_1286), level(_1424 * half(4.0)));
    half3 _1042 = half4(frame.lightColor).xyz;
    float3 _1577 = fast::normalize(_987 + frame.lightDirection.xyz);
    half _1509 = clamp(dot(_981, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1513 = clamp(dot(_981, half3(_1577)), half(0.0), half(1.0));
    half _1617 = half(4096.0) * half(params.facet_alpha);
    half4 _1642 = half4(cross(_981, half3(_1577)), half(params.facet_alpha) * _1513) * half(64.0);
    half _1623 = _1617 / dot(_1642, _1642);
    half _1653 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1659 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1663 = sqrt(fma(_1282 * _1282, _1659, _1653));
    half _1687 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1577)), half(0.0), half(1.0));
    half _1690 = _1687 * _1687;
    half3 _1698 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1731 = half(8192.0) * fma(half(-float(_1509)), _1282, _1509 + _1282);
    half _1735 = half(1.0) / (_1440 * _1731);
    half _1742 = half(2048.0) * _1440;
    half3 _1550 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    half3 _1558 = min(fma(fma((half3(float3(params.facet_f0)) + (_1698 * ((_1690 * _1690) * _1687))) * min(min((_1623 * _1623) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1509, _1663, _1282 * sqrt(fma(_1509 * _1509, _1659, _1653))), half(65504.0)), half(65504.0)), _1340, _1550), (_1042 * _1509) * _1396, (_1431 * ((((fma(_1735, _1731, half(2.0)) * pow(max(fma(half(-float(_1513)), _1513, half(1.0)), half(0.0)), half(0.5) * (_1735 * _1731))) * half(0.15915493667125701904296875)) * (_1509 * (_1735 * _1742))) * _1401)) * _1042), half3(float3(65504.0)));
    float3 _1806 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1809 = dot(_1806, _1806);
    float3 _1814 = _1806 * rsqrt(fast::max(_1809, 9.9999999392252902907785028219223e-09));
    float _1818 = _1809 * float(frame.punctualLights[0].positionFalloff.w);
    float _1823 = fast::clamp(fma(-_1818, _1818, 1.0), 0.0, 1.0);
    float _1842 = fast::clamp(fma(dot(-_1814, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1853 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1823) * half(_1823)) / fast::max(_1809, 9.9999997473787516355514526367188e-05)) * half(_1842)) * half(_1842)), float3(65504.0));
    float3 _1978 = fast::normalize(_987 + _1814);
    half _1910 = clamp(dot(_981, half3(_1814)), half(0.0), half(1.0));
    half _1914 = clamp(dot(_981, half3(_1978)), half(0.0), half(1.0));
    half4 _2043 = half4(cross(_981, half3(_1978)), half(params.facet_alpha) * _1914) * half(64.0);
    half _2024 = _1617 / dot(_2043, _2043);
    half _2088 = half(1.0) - clamp(dot(half3(_1814), half3(_1978)), half(0.0), half(1.0));
    half _2091 = _2088 * _2088;
    half _2132 = half(8192.0) * fma(half(-float(_1910)), _1282, _1910 + _1282);
    half _2136 = half(1.0) / (_1440 * _2132);
    half3 _1959 = min(fma(fma((half3(float3(params.facet_f0)) + (_1698 * ((_2091 * _2091) * _2088))) * min(min((_2024 * _2024) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1910, _1663, _1282 * sqrt(fma(_1910 * _1910, _1659, _1653))), half(65504.0)), half(65504.0)), _1340, _1550), (half3(_1853) * _1910) * _1396, (_1431 * ((((fma(_2136, _2132, half(2.0)) * pow(max(fma(half(-float(_1914)), _1914, half(1.0)), half(0.0)), half(0.5) * (_2136 * _2132))) * half(0.15915493667125701904296875)) * (_1910 * (_2136 * _1742))) * _1401)) * half3(_1853)), half3(float3(65504.0)));
    float3 _2207 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2210 = dot(_2207, _2207);
    float3 _2215 = _2207 * rsqrt(fast::max(_2210, 9.9999999392252902907785028219223e-09));
    float _2219 = _2210 * float(frame.punctualLights[1].positionFalloff.w);
    float _2224 = fast::clamp(fma(-_2219, _2219, 1.0), 0.0, 1.0);
    float _2243 = fast::clamp(fma(dot(-_2215, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2254 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2224) * half(_2224)) / fast::max(_2210, 9.9999997473787516355514526367188e-05)) * half(_2243)) * half(_2243)), float3(65504.0));
    float3 _2379 = fast::normalize(_987 + _2215);
    half _2311 = clamp(dot(_981, half3(_2215)), half(0.0), half(1.0));
    half _2315 = clamp(dot(_981, half3(_2379)), half(0.0), half(1.0));
    half4 _2444 = half4(cross(_981, half3(_2379)), half(params.facet_alpha) * _2315) * half(64.0);
    half _2425 = _1617 / dot(_2444, _2444);
    half _2489 = half(1.0) - clamp(dot(half3(_2215), half3(_2379)), half(0.0), half(1.0));
    half _2492 = _2489 * _2489;
    half _2533 = half(8192.0) * fma(half(-float(_2311)), _1282, _2311 + _1282);
    half _2537 = half(1.0) / (_1440 * _2533);
    half3 _2360 = min(fma(fma((half3(float3(params.facet_f0)) + (_1698 * ((_2492 * _2492) * _2489))) * min(min((_2425 * _2425) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2311, _1663, _1282 * sqrt(fma(_2311 * _2311, _1659, _1653))), half(65504.0)), half(65504.0)), _1340, _1550), (half3(_2254) * _2311) * _1396, (_1431 * ((((fma(_2537, _2533, half(2.0)) * pow(max(fma(half(-float(_2315)), _2315, half(1.0)), half(0.0)), half(0.5) * (_2537 * _2533))) * half(0.15915493667125701904296875)) * (_2311 * (_2537 * _1742))) * _1401)) * half3(_2254)), half3(float3(65504.0)));
    out.fragColor = float4(half4(((fma(half4(_1452).xyz, _1431 * _1394, fma(half3(float3(params.facet_diffuseColor)), _1232, half4(_1347).xyz * (mix(half4(_1321).xxx, half4(_1321).yyy, half3(float3(params.facet_f0))) * _1340)) * _1396) + _1558) + _1959) + _2360, half(1.0)));
    return out;
}

