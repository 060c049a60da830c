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
    half3 _976 = normalize(half3(in.v_normal));
    float3 _982 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1265 = max(dot(_976, half3(_982)), half(9.9999997473787516355514526367188e-05));
    half3 _1269 = reflect(-half3(_982), _976);
    float4 _1304 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1265, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1323 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1304).y) - half(1.0)));
    float4 _1333 = facet_environment.sample(facet_environmentSmplr, float3(_1269), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1381 = half(1.0) - _1265;
    half _1384 = _1381 * _1381;
    half _1391 = fma(half(0.959999978542327880859375), (_1384 * _1384) * _1381, half(0.039999999105930328369140625));
    half _1396 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1363 = fma(half(-float(_1391)), _1396, half(1.0));
    half _1401 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1411 = facet_environment.sample(facet_environmentSmplr, float3(_1269), level(_1401 * (half(4.0) * (half(2.0) - _1401))));
    float3 _1448 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1451 = dot(_1448, _1448);
    float3 _1456 = _1448 * rsqrt(fast::max(_1451, 9.9999999392252902907785028219223e-09));
    float _1460 = _1451 * float(frame.punctualLights[0].positionFalloff.w);
    float _1465 = fast::clamp(fma(-_1460, _1460, 1.0), 0.0, 1.0);
    float _1484 = fast::clamp(fma(dot(-_1456, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1620 = fast::normalize(_982 + _1456);
    half _1552 = clamp(dot(_976, half3(_1456)), half(0.0), half(1.0));
    half _1556 = clamp(dot(_976, half3(_1620)), half(0.0), half(1.0));
    half _1560 = clamp(dot(half3(_1456), half3(_1620)), half(0.0), half(1.0));
    half _1660 = half(4096.0) * half(params.facet_alpha);
    half3 _1679 = cross(_976, half3(_1620)) * half(64.0);
    half _1681 = half(64.0) * half(params.facet_alpha);
    half _1683 = _1681 * _1556;
    half _1686 = dot(_1679, _1679);
    half _1666 = _1660 / fma(_1683, _1683, _1686);
    half _1698 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1704 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1708 = sqrt(fma(_1265 * _1265, _1704, _1698));
    half _1732 = half(1.0) - _1560;
    half _1735 = _1732 * _1732;
    half _1740 = (_1735 * _1735) * _1732;
    half3 _1743 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1775 = _1401 * _1401;
    half _1832 = half(64.0) * _1775;
    half _1834 = _1832 * _1556;
    half _1785 = half(12.56637096405029296875) * max(_1560 * _1560, half(6.103515625e-05));
    half _1787 = half(4096.0) * _1775;
    half _1791 = _1787 / (fma(_1834, _1834, _1686) * _1785);
    half _1809 = half(0.959999978542327880859375) * _1396;
    half3 _1601 = min(min(((((half3(float3(params.facet_f0)) + (_1743 * _1740)) * min(min((_1666 * _1666) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1552, _1708, _1265 * sqrt(fma(_1552 * _1552, _1704, _1698))), half(65504.0)), half(65504.0))) * _1323) * _1363) + half3(min(_1791 * (_1791 * _1785), half(65504.0)) * fma(half(0.039999999105930328369140625), _1396, _1809 * _1740)), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1465) * half(_1465)) / fast::max(_1451, 9.9999997473787516355514526367188e-05)) * half(_1484)) * half(_1484)), float3(65504.0))) * _1552), half3(float3(65504.0)));
    float3 _1901 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1904 = dot(_1901, _1901);
    float3 _1909 = _1901 * rsqrt(fast::max(_1904, 9.9999999392252902907785028219223e-09));
    float _1913 = _1904 * float(frame.punctualLights[1].positionFalloff.w);
    float _1918 = fast::clamp(fma(-_1913, _1913, 1.0), 0.0, 1.0);
    float _1937 = fast::clamp(fma(dot(-_1909, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2073 = fast::normalize(_982 + _1909);
    half _2005 = clamp(dot(_976, half3(_1909)), half(0.0), half(1.0));
    half _2009 = clamp(dot(_976, half3(_2073)), half(0.0), half(1.0));
    half _2013 = clamp(dot(half3(_1909), half3(_2073)), half(0.0), half(1.0));
    half3 _2132 = cross(_976, half3(_2073)) * half(64.0);
    half _2136 = _1681 * _2009;
    half _2139 = dot(_2132, _2132);
    half _2119 = _1660 / fma(_2136, _2136, _2139);
    half _2185 = half(1.0) - _2013;
    half _2188 = _2185 * _2185;
    half _2193 = (_2188 * _2188) * _2185;
    half _2287 = _1832 * _2009;
    half _2238 = half(12.56637096405029296875) * max(_2013 * _2013, half(6.103515625e-05));
    half _2244 = _1787 / (fma(_2287, _2287, _2139) * _2238);
    half3 _2054 = min(min(((((half3(float3(params.facet_f0)) + (_1743 * _2193)) * min(min((_2119 * _2119) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2005, _1708, _1265 * sqrt(fma(_2005 * _2005, _1704, _1698))), half(65504.0)), half(65504.0))) * _1323) * _1363) + half3(min(_2244 * (_2244 * _2238), half(65504.0)) * fma(half(0.039999999105930328369140625), _1396, _1809 * _2193)), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1918) * half(_1918)) / fast::max(_1904, 9.9999997473787516355514526367188e-05)) * half(_1937)) * half(_1937)), float3(65504.0))) * _2005), half3(float3(65504.0)));
    out.fragColor = float4(half4((mix(half4(_1333).xyz * (mix(half4(_1304).xxx, half4(_1304).yyy, half3(float3(params.facet_f0))) * _1323), half4(_1411).xyz, half3(_1391 * _1396)) + _1601) + _2054, half(1.0)));
    return out;
}

