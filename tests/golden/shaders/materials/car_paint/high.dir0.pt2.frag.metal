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
    half3 _943 = normalize(half3(in.v_normal));
    float3 _949 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1235 = max(dot(_943, half3(_949)), half(9.9999997473787516355514526367188e-05));
    half3 _1239 = reflect(-half3(_949), _943);
    float4 _1274 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1235, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1293 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1274).y) - half(1.0)));
    float4 _1300 = facet_environment.sample(facet_environmentSmplr, float3(_1239), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1348 = half(1.0) - _1235;
    half _1351 = _1348 * _1348;
    half _1358 = fma(half(0.959999978542327880859375), (_1351 * _1351) * _1348, half(0.039999999105930328369140625));
    half _1363 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1330 = fma(half(-float(_1358)), _1363, half(1.0));
    half _1368 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1375 = facet_environment.sample(facet_environmentSmplr, float3(_1239), level(_1368 * half(4.0)));
    float3 _1412 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1415 = dot(_1412, _1412);
    float3 _1420 = _1412 * rsqrt(fast::max(_1415, 9.9999999392252902907785028219223e-09));
    float _1424 = _1415 * float(frame.punctualLights[0].positionFalloff.w);
    float _1429 = fast::clamp(fma(-_1424, _1424, 1.0), 0.0, 1.0);
    float _1448 = fast::clamp(fma(dot(-_1420, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1584 = fast::normalize(_949 + _1420);
    half _1517 = clamp(dot(_943, half3(_1420)), half(0.0), half(1.0));
    half _1521 = clamp(dot(_943, half3(_1584)), half(0.0), half(1.0));
    half _1525 = clamp(dot(half3(_1420), half3(_1584)), half(0.0), half(1.0));
    half3 _1624 = cross(_943, half3(_1584));
    half _1627 = _1521 * half(params.facet_alpha);
    half _1631 = dot(_1624, _1624);
    half _1636 = half(params.facet_alpha) / fma(_1627, _1627, _1631);
    half _1650 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1656 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1660 = sqrt(fma(_1235 * _1235, _1656, _1650));
    half _1684 = half(1.0) - _1525;
    half _1687 = _1684 * _1684;
    half _1692 = (_1687 * _1687) * _1684;
    half3 _1695 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1543 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1429) * half(_1429)) / fast::max(_1415, 9.9999997473787516355514526367188e-05)) * half(_1448)) * half(_1448)), float3(65504.0))) * _1517;
    half _1733 = _1368 * _1368;
    half _1786 = _1521 * _1733;
    half _1795 = _1733 / fma(_1786, _1786, _1631);
    float3 _1863 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1866 = dot(_1863, _1863);
    float3 _1871 = _1863 * rsqrt(fast::max(_1866, 9.9999999392252902907785028219223e-09));
    float _1875 = _1866 * float(frame.punctualLights[1].positionFalloff.w);
    float _1880 = fast::clamp(fma(-_1875, _1875, 1.0), 0.0, 1.0);
    float _1899 = fast::clamp(fma(dot(-_1871, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2035 = fast::normalize(_949 + _1871);
    half _1968 = clamp(dot(_943, half3(_1871)), half(0.0), half(1.0));
    half _1972 = clamp(dot(_943, half3(_2035)), half(0.0), half(1.0));
    half _1976 = clamp(dot(half3(_1871), half3(_2035)), half(0.0), half(1.0));
    half3 _2075 = cross(_943, half3(_2035));
    half _2078 = _1972 * half(params.facet_alpha);
    half _2082 = dot(_2075, _2075);
    half _2087 = half(params.facet_alpha) / fma(_2078, _2078, _2082);
    half _2135 = half(1.0) - _1976;
    half _2138 = _2135 * _2135;
    half _2143 = (_2138 * _2138) * _2135;
    half3 _1994 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1880) * half(_1880)) / fast::max(_1866, 9.9999997473787516355514526367188e-05)) * half(_1899)) * half(_1899)), float3(65504.0))) * _1968;
    half _2237 = _1972 * _1733;
    half _2246 = _1733 / fma(_2237, _2237, _2082);
    half3 _2278 = (mix(half4(_1300).xyz * (mix(half4(_1274).xxx, half4(_1274).yyy, half3(float3(params.facet_f0))) * _1293), half4(_1375).xyz, half3(_1358 * _1363)) + min(fma(((half3(float3(params.facet_f0)) + (_1695 * _1692)) * min(min((_1636 * _1636) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1517, _1660, _1235 * sqrt(fma(_1517 * _1517, _1656, _1650))), half(65504.0)), half(65504.0))) * _1293, _1543 * _1330, _1543 * (min(min((_1795 * _1795) * half(0.3183098733425140380859375), half(65504.0)) * (half(0.25) / max(_1525 * _1525, half(6.103515625e-05))), half(65504.0)) * (fma(half(0.959999978542327880859375), _1692, half(0.039999999105930328369140625)) * _1363))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1695 * _2143)) * min(min((_2087 * _2087) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1968, _1660, _1235 * sqrt(fma(_1968 * _1968, _1656, _1650))), half(65504.0)), half(65504.0))) * _1293, _1994 * _1330, _1994 * (min(min((_2246 * _2246) * half(0.3183098733425140380859375), half(65504.0)) * (half(0.25) / max(_1976 * _1976, half(6.103515625e-05))), half(65504.0)) * (fma(half(0.959999978542327880859375), _2143, half(0.039999999105930328369140625)) * _1363))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2278, half(1.0)));
    return out;
}

