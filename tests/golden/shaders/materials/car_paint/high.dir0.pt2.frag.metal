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
    half3 _964 = normalize(half3(in.v_normal));
    float3 _970 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1253 = max(dot(_964, half3(_970)), half(9.9999997473787516355514526367188e-05));
    half3 _1257 = reflect(-half3(_970), _964);
    float4 _1292 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1253, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1311 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1292).y) - half(1.0)));
    float4 _1323 = facet_environment.sample(facet_environmentSmplr, float3(_1257), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1371 = half(1.0) - _1253;
    half _1374 = _1371 * _1371;
    half _1381 = fma(half(0.959999978542327880859375), (_1374 * _1374) * _1371, half(0.039999999105930328369140625));
    half _1386 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1353 = fma(half(-float(_1381)), _1386, half(1.0));
    half _1391 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1403 = facet_environment.sample(facet_environmentSmplr, float3(_1257), level(_1391 * (half(4.0) * (half(2.0) - _1391))));
    float3 _1440 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1443 = dot(_1440, _1440);
    float3 _1448 = _1440 * rsqrt(fast::max(_1443, 9.9999999392252902907785028219223e-09));
    float _1452 = _1443 * float(frame.punctualLights[0].positionFalloff.w);
    float _1457 = fast::clamp(fma(-_1452, _1452, 1.0), 0.0, 1.0);
    float _1476 = fast::clamp(fma(dot(-_1448, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1612 = fast::normalize(_970 + _1448);
    half _1545 = clamp(dot(_964, half3(_1448)), half(0.0), half(1.0));
    half _1549 = clamp(dot(_964, half3(_1612)), half(0.0), half(1.0));
    half _1553 = clamp(dot(half3(_1448), half3(_1612)), half(0.0), half(1.0));
    half3 _1652 = cross(_964, half3(_1612));
    half _1655 = _1549 * half(params.facet_alpha);
    half _1659 = dot(_1652, _1652);
    half _1664 = half(params.facet_alpha) / fma(_1655, _1655, _1659);
    half _1678 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1684 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1688 = sqrt(fma(_1253 * _1253, _1684, _1678));
    half _1712 = half(1.0) - _1553;
    half _1715 = _1712 * _1712;
    half _1720 = (_1715 * _1715) * _1712;
    half3 _1723 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1571 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1457) * half(_1457)) / fast::max(_1443, 9.9999997473787516355514526367188e-05)) * half(_1476)) * half(_1476)), float3(65504.0))) * _1545;
    half _1757 = _1391 * _1391;
    half _1763 = _1549 * _1757;
    half _1774 = max(_1553 * _1553, half(6.103515625e-05));
    half _1777 = half(2048.0) * _1757;
    half _1782 = _1777 / (fma(_1763, _1763, _1659) * (_1774 * half(25735.927734375)));
    float3 _1881 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1884 = dot(_1881, _1881);
    float3 _1889 = _1881 * rsqrt(fast::max(_1884, 9.9999999392252902907785028219223e-09));
    float _1893 = _1884 * float(frame.punctualLights[1].positionFalloff.w);
    float _1898 = fast::clamp(fma(-_1893, _1893, 1.0), 0.0, 1.0);
    float _1917 = fast::clamp(fma(dot(-_1889, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2053 = fast::normalize(_970 + _1889);
    half _1986 = clamp(dot(_964, half3(_1889)), half(0.0), half(1.0));
    half _1990 = clamp(dot(_964, half3(_2053)), half(0.0), half(1.0));
    half _1994 = clamp(dot(half3(_1889), half3(_2053)), half(0.0), half(1.0));
    half3 _2093 = cross(_964, half3(_2053));
    half _2096 = _1990 * half(params.facet_alpha);
    half _2100 = dot(_2093, _2093);
    half _2105 = half(params.facet_alpha) / fma(_2096, _2096, _2100);
    half _2153 = half(1.0) - _1994;
    half _2156 = _2153 * _2153;
    half _2161 = (_2156 * _2156) * _2153;
    half3 _2012 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1898) * half(_1898)) / fast::max(_1884, 9.9999997473787516355514526367188e-05)) * half(_1917)) * half(_1917)), float3(65504.0))) * _1986;
    half _2204 = _1990 * _1757;
    half _2215 = max(_1994 * _1994, half(6.103515625e-05));
    half _2223 = _1777 / (fma(_2204, _2204, _2100) * (_2215 * half(25735.927734375)));
    half3 _2286 = (mix(half4(_1323).xyz * (mix(half4(_1292).xxx, half4(_1292).yyy, half3(float3(params.facet_f0))) * _1311), half4(_1403).xyz, half3(_1381 * _1386)) + min(fma(((half3(float3(params.facet_f0)) + (_1723 * _1720)) * min(min((_1664 * _1664) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1545, _1688, _1253 * sqrt(fma(_1545 * _1545, _1684, _1678))), half(65504.0)), half(65504.0))) * _1311, _1571 * _1353, _1571 * (min(_1782 * (_1782 * (half(12.56637096405029296875) * _1774)), half(65504.0)) * (fma(half(0.959999978542327880859375), _1720, half(0.039999999105930328369140625)) * _1386))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1723 * _2161)) * min(min((_2105 * _2105) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1986, _1688, _1253 * sqrt(fma(_1986 * _1986, _1684, _1678))), half(65504.0)), half(65504.0))) * _1311, _2012 * _1353, _2012 * (min(_2223 * (_2223 * (half(12.56637096405029296875) * _2215)), half(65504.0)) * (fma(half(0.959999978542327880859375), _2161, half(0.039999999105930328369140625)) * _1386))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2286, half(1.0)));
    return out;
}

