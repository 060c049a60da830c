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
    half3 _984 = normalize(half3(in.v_normal));
    float3 _990 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1157 = _984.y;
    half _1162 = _984.z;
    half _1167 = _984.x;
    half3 _1235 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1157)) + (half4(frame.sh[2]).xyz * _1162)) + (half4(frame.sh[3]).xyz * _1167)) + (((((half4(frame.sh[4]).xyz * (_1167 * _1157)) + (half4(frame.sh[5]).xyz * (_1157 * _1162))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1162, _1162, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1167 * _1162))) + (half4(frame.sh[8]).xyz * fma(_1167, _1167, half(-float(_1157 * _1157))))), half3(float3(0.0)));
    half _1285 = max(dot(_984, half3(_990)), half(9.9999997473787516355514526367188e-05));
    half3 _1289 = reflect(-half3(_990), _984);
    float4 _1324 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1285, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1343 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1324).y) - half(1.0)));
    float4 _1353 = facet_environment.sample(facet_environmentSmplr, float3(_1289), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1430 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1387 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1285, _1430)), level(0.0));
    half3 _1437 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2783 = half4(_1387);
    half _1400 = _2783.z;
    half _1402 = fma(half(-float(max(_1437.x, max(_1437.y, _1437.z)))), _1400, half(1.0));
    half _1446 = _1430 * _1430;
    half4 _2787 = half4(_1387);
    half _1407 = _2787.w;
    float4 _1461 = facet_environment.sample(facet_environmentSmplr, float3(_1289), level(_1430 * (half(4.0) * (half(2.0) - _1430))));
    half3 _1045 = half4(frame.lightColor).xyz;
    float3 _1586 = fast::normalize(_990 + frame.lightDirection.xyz);
    half _1518 = clamp(dot(_984, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1522 = clamp(dot(_984, half3(_1586)), half(0.0), half(1.0));
    half _1626 = half(4096.0) * half(params.facet_alpha);
    half4 _1651 = half4(cross(_984, half3(_1586)), half(params.facet_alpha) * _1522) * half(64.0);
    half _1632 = _1626 / dot(_1651, _1651);
    half _1662 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1668 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1672 = sqrt(fma(_1285 * _1285, _1668, _1662));
    half _1696 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1586)), half(0.0), half(1.0));
    half _1699 = _1696 * _1696;
    half3 _1707 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1740 = half(8192.0) * fma(half(-float(_1518)), _1285, _1518 + _1285);
    half _1744 = half(1.0) / (_1446 * _1740);
    half _1751 = half(2048.0) * _1446;
    half3 _1559 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    half3 _1567 = min(fma(fma((half3(float3(params.facet_f0)) + (_1707 * ((_1699 * _1699) * _1696))) * min(min((_1632 * _1632) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1518, _1672, _1285 * sqrt(fma(_1518 * _1518, _1668, _1662))), half(65504.0)), half(65504.0)), _1343, _1559), (_1045 * _1518) * _1402, (_1437 * ((((fma(_1744, _1740, half(2.0)) * pow(max(fma(half(-float(_1522)), _1522, half(1.0)), half(0.0)), half(0.5) * (_1744 * _1740))) * half(0.15915493667125701904296875)) * (_1518 * (_1744 * _1751))) * _1407)) * _1045), half3(float3(65504.0)));
    float3 _1815 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1818 = dot(_1815, _1815);
    float3 _1823 = _1815 * rsqrt(fast::max(_1818, 9.9999999392252902907785028219223e-09));
    float _1827 = _1818 * float(frame.punctualLights[0].positionFalloff.w);
    float _1832 = fast::clamp(fma(-_1827, _1827, 1.0), 0.0, 1.0);
    float _1851 = fast::clamp(fma(dot(-_1823, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1862 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1832) * half(_1832)) / fast::max(_1818, 9.9999997473787516355514526367188e-05)) * half(_1851)) * half(_1851)), float3(65504.0));
    float3 _1987 = fast::normalize(_990 + _1823);
    half _1919 = clamp(dot(_984, half3(_1823)), half(0.0), half(1.0));
    half _1923 = clamp(dot(_984, half3(_1987)), half(0.0), half(1.0));
    half4 _2052 = half4(cross(_984, half3(_1987)), half(params.facet_alpha) * _1923) * half(64.0);
    half _2033 = _1626 / dot(_2052, _2052);
    half _2097 = half(1.0) - clamp(dot(half3(_1823), half3(_1987)), half(0.0), half(1.0));
    half _2100 = _2097 * _2097;
    half _2141 = half(8192.0) * fma(half(-float(_1919)), _1285, _1919 + _1285);
    half _2145 = half(1.0) / (_1446 * _2141);
    half3 _1968 = min(fma(fma((half3(float3(params.facet_f0)) + (_1707 * ((_2100 * _2100) * _2097))) * min(min((_2033 * _2033) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1919, _1672, _1285 * sqrt(fma(_1919 * _1919, _1668, _1662))), half(65504.0)), half(65504.0)), _1343, _1559), (half3(_1862) * _1919) * _1402, (_1437 * ((((fma(_2145, _2141, half(2.0)) * pow(max(fma(half(-float(_1923)), _1923, half(1.0)), half(0.0)), half(0.5) * (_2145 * _2141))) * half(0.15915493667125701904296875)) * (_1919 * (_2145 * _1751))) * _1407)) * half3(_1862)), half3(float3(65504.0)));
    float3 _2216 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2219 = dot(_2216, _2216);
    float3 _2224 = _2216 * rsqrt(fast::max(_2219, 9.9999999392252902907785028219223e-09));
    float _2228 = _2219 * float(frame.punctualLights[1].positionFalloff.w);
    float _2233 = fast::clamp(fma(-_2228, _2228, 1.0), 0.0, 1.0);
    float _2252 = fast::clamp(fma(dot(-_2224, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2263 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2233) * half(_2233)) / fast::max(_2219, 9.9999997473787516355514526367188e-05)) * half(_2252)) * half(_2252)), float3(65504.0));
    float3 _2388 = fast::normalize(_990 + _2224);
    half _2320 = clamp(dot(_984, half3(_2224)), half(0.0), half(1.0));
    half _2324 = clamp(dot(_984, half3(_2388)), half(0.0), half(1.0));
    half4 _2453 = half4(cross(_984, half3(_2388)), half(params.facet_alpha) * _2324) * half(64.0);
    half _2434 = _1626 / dot(_2453, _2453);
    half _2498 = half(1.0) - clamp(dot(half3(_2224), half3(_2388)), half(0.0), half(1.0));
    half _2501 = _2498 * _2498;
    half _2542 = half(8192.0) * fma(half(-float(_2320)), _1285, _2320 + _1285);
    half _2546 = half(1.0) / (_1446 * _2542);
    half3 _2369 = min(fma(fma((half3(float3(params.facet_f0)) + (_1707 * ((_2501 * _2501) * _2498))) * min(min((_2434 * _2434) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2320, _1672, _1285 * sqrt(fma(_2320 * _2320, _1668, _1662))), half(65504.0)), half(65504.0)), _1343, _1559), (half3(_2263) * _2320) * _1402, (_1437 * ((((fma(_2546, _2542, half(2.0)) * pow(max(fma(half(-float(_2324)), _2324, half(1.0)), half(0.0)), half(0.5) * (_2546 * _2542))) * half(0.15915493667125701904296875)) * (_2320 * (_2546 * _1751))) * _1407)) * half3(_2263)), half3(float3(65504.0)));
    out.fragColor = float4(half4(((fma(half4(_1461).xyz, _1437 * _1400, fma(half3(float3(params.facet_diffuseColor)), _1235, half4(_1353).xyz * (mix(half4(_1324).xxx, half4(_1324).yyy, half3(float3(params.facet_f0))) * _1343)) * _1402) + _1567) + _1968) + _2369, half(1.0)));
    return out;
}

