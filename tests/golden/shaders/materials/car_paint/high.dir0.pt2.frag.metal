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
    half3 _968 = normalize(half3(in.v_normal));
    float3 _974 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1257 = max(dot(_968, half3(_974)), half(9.9999997473787516355514526367188e-05));
    half3 _1261 = reflect(-half3(_974), _968);
    float4 _1296 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1257, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1315 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1296).y) - half(1.0)));
    float4 _1322 = facet_environment.sample(facet_environmentSmplr, float3(_1261), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1370 = half(1.0) - _1257;
    half _1373 = _1370 * _1370;
    half _1380 = fma(half(0.959999978542327880859375), (_1373 * _1373) * _1370, half(0.039999999105930328369140625));
    half _1385 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1352 = fma(half(-float(_1380)), _1385, half(1.0));
    half _1390 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1397 = facet_environment.sample(facet_environmentSmplr, float3(_1261), level(_1390 * half(4.0)));
    float3 _1434 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1437 = dot(_1434, _1434);
    float3 _1442 = _1434 * rsqrt(fast::max(_1437, 9.9999999392252902907785028219223e-09));
    float _1446 = _1437 * float(frame.punctualLights[0].positionFalloff.w);
    float _1451 = fast::clamp(fma(-_1446, _1446, 1.0), 0.0, 1.0);
    float _1470 = fast::clamp(fma(dot(-_1442, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1606 = fast::normalize(_974 + _1442);
    half _1539 = clamp(dot(_968, half3(_1442)), half(0.0), half(1.0));
    half _1543 = clamp(dot(_968, half3(_1606)), half(0.0), half(1.0));
    half _1547 = clamp(dot(half3(_1442), half3(_1606)), half(0.0), half(1.0));
    half _1646 = half(4096.0) * half(params.facet_alpha);
    half3 _1663 = cross(_968, half3(_1606));
    half _1667 = _1663.x;
    half4 _1671 = half4(_1667, _1663.yz, half(params.facet_alpha) * _1543) * half(64.0);
    half _1652 = _1646 / dot(_1671, _1671);
    half _1682 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1688 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1692 = sqrt(fma(_1257 * _1257, _1688, _1682));
    half _1716 = half(1.0) - _1547;
    half _1719 = _1716 * _1716;
    half _1724 = (_1719 * _1719) * _1716;
    half3 _1727 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1565 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1451) * half(_1451)) / fast::max(_1437, 9.9999997473787516355514526367188e-05)) * half(_1470)) * half(_1470)), float3(65504.0))) * _1539;
    half _1763 = _1390 * _1390;
    half4 _1816 = half4(_1667, _1663.yz, _1763 * _1543) * half(64.0);
    half _1773 = half(12.56637096405029296875) * max(_1547 * _1547, half(6.103515625e-05));
    half _1775 = half(4096.0) * _1763;
    half _1779 = _1775 / (dot(_1816, _1816) * _1773);
    float3 _1895 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1898 = dot(_1895, _1895);
    float3 _1903 = _1895 * rsqrt(fast::max(_1898, 9.9999999392252902907785028219223e-09));
    float _1907 = _1898 * float(frame.punctualLights[1].positionFalloff.w);
    float _1912 = fast::clamp(fma(-_1907, _1907, 1.0), 0.0, 1.0);
    float _1931 = fast::clamp(fma(dot(-_1903, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2067 = fast::normalize(_974 + _1903);
    half _2000 = clamp(dot(_968, half3(_1903)), half(0.0), half(1.0));
    half _2004 = clamp(dot(_968, half3(_2067)), half(0.0), half(1.0));
    half _2008 = clamp(dot(half3(_1903), half3(_2067)), half(0.0), half(1.0));
    half3 _2124 = cross(_968, half3(_2067));
    half _2128 = _2124.x;
    half4 _2132 = half4(_2128, _2124.yz, half(params.facet_alpha) * _2004) * half(64.0);
    half _2113 = _1646 / dot(_2132, _2132);
    half _2177 = half(1.0) - _2008;
    half _2180 = _2177 * _2177;
    half _2185 = (_2180 * _2180) * _2177;
    half3 _2026 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1912) * half(_1912)) / fast::max(_1898, 9.9999997473787516355514526367188e-05)) * half(_1931)) * half(_1931)), float3(65504.0))) * _2000;
    half4 _2277 = half4(_2128, _2124.yz, _1763 * _2004) * half(64.0);
    half _2234 = half(12.56637096405029296875) * max(_2008 * _2008, half(6.103515625e-05));
    half _2240 = _1775 / (dot(_2277, _2277) * _2234);
    half3 _2320 = (mix(half4(_1322).xyz * (mix(half4(_1296).xxx, half4(_1296).yyy, half3(float3(params.facet_f0))) * _1315), half4(_1397).xyz, half3(_1380 * _1385)) + min(fma(((half3(float3(params.facet_f0)) + (_1727 * _1724)) * min(min((_1652 * _1652) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1539, _1692, _1257 * sqrt(fma(_1539 * _1539, _1688, _1682))), half(65504.0)), half(65504.0))) * _1315, _1565 * _1352, _1565 * (min(_1779 * (_1779 * _1773), half(65504.0)) * (fma(half(0.959999978542327880859375), _1724, half(0.039999999105930328369140625)) * _1385))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1727 * _2185)) * min(min((_2113 * _2113) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2000, _1692, _1257 * sqrt(fma(_2000 * _2000, _1688, _1682))), half(65504.0)), half(65504.0))) * _1315, _2026 * _1352, _2026 * (min(_2240 * (_2240 * _2234), half(65504.0)) * (fma(half(0.959999978542327880859375), _2185, half(0.039999999105930328369140625)) * _1385))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2320, half(1.0)));
    return out;
}

