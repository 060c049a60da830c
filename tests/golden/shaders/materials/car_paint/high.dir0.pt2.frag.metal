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
    half _1346 = half(1.0) - _1235;
    half _1349 = _1346 * _1346;
    half _1361 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1366 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1373 = facet_environment.sample(facet_environmentSmplr, float3(_1239), level(_1366 * half(4.0)));
    float3 _1410 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1413 = dot(_1410, _1410);
    float3 _1418 = _1410 * rsqrt(fast::max(_1413, 9.9999999392252902907785028219223e-09));
    float _1422 = _1413 * float(frame.punctualLights[0].positionFalloff.w);
    float _1427 = fast::clamp(fma(-_1422, _1422, 1.0), 0.0, 1.0);
    float _1446 = fast::clamp(fma(dot(-_1418, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1586 = fast::normalize(_949 + _1418);
    half _1517 = clamp(dot(_943, half3(_1418)), half(0.0), half(1.0));
    half _1521 = clamp(dot(_943, half3(_1586)), half(0.0), half(1.0));
    half _1525 = clamp(dot(half3(_1418), half3(_1586)), half(0.0), half(1.0));
    half3 _1626 = cross(_943, half3(_1586));
    half _1629 = _1521 * half(params.facet_alpha);
    half _1633 = dot(_1626, _1626);
    half _1638 = half(params.facet_alpha) / fma(_1629, _1629, _1633);
    half _1652 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1658 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1662 = sqrt(fma(_1235 * _1235, _1658, _1652));
    half _1686 = half(1.0) - _1525;
    half _1689 = _1686 * _1686;
    half _1694 = (_1689 * _1689) * _1686;
    half3 _1697 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1543 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1427) * half(_1427)) / fast::max(_1413, 9.9999997473787516355514526367188e-05)) * half(_1446)) * half(_1446)), float3(65504.0))) * _1517;
    half _1770 = fma(half(0.959999978542327880859375), _1694, half(0.039999999105930328369140625));
    half _1734 = _1366 * _1366;
    half _1787 = _1521 * _1734;
    half _1796 = _1734 / fma(_1787, _1787, _1633);
    float3 _1864 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1867 = dot(_1864, _1864);
    float3 _1872 = _1864 * rsqrt(fast::max(_1867, 9.9999999392252902907785028219223e-09));
    float _1876 = _1867 * float(frame.punctualLights[1].positionFalloff.w);
    float _1881 = fast::clamp(fma(-_1876, _1876, 1.0), 0.0, 1.0);
    float _1900 = fast::clamp(fma(dot(-_1872, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2040 = fast::normalize(_949 + _1872);
    half _1971 = clamp(dot(_943, half3(_1872)), half(0.0), half(1.0));
    half _1975 = clamp(dot(_943, half3(_2040)), half(0.0), half(1.0));
    half _1979 = clamp(dot(half3(_1872), half3(_2040)), half(0.0), half(1.0));
    half3 _2080 = cross(_943, half3(_2040));
    half _2083 = _1975 * half(params.facet_alpha);
    half _2087 = dot(_2080, _2080);
    half _2092 = half(params.facet_alpha) / fma(_2083, _2083, _2087);
    half _2140 = half(1.0) - _1979;
    half _2143 = _2140 * _2140;
    half _2148 = (_2143 * _2143) * _2140;
    half3 _1997 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1881) * half(_1881)) / fast::max(_1867, 9.9999997473787516355514526367188e-05)) * half(_1900)) * half(_1900)), float3(65504.0))) * _1971;
    half _2224 = fma(half(0.959999978542327880859375), _2148, half(0.039999999105930328369140625));
    half _2241 = _1975 * _1734;
    half _2250 = _1734 / fma(_2241, _2241, _2087);
    half3 _2282 = (mix(half4(_1300).xyz * (mix(half4(_1274).xxx, half4(_1274).yyy, half3(float3(params.facet_f0))) * _1293), half4(_1373).xyz, half3(fma(half(0.959999978542327880859375), (_1349 * _1349) * _1346, half(0.039999999105930328369140625)) * _1361)) + min(fma(((half3(float3(params.facet_f0)) + (_1697 * _1694)) * min(min((_1638 * _1638) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1517, _1662, _1235 * sqrt(fma(_1517 * _1517, _1658, _1652))), half(65504.0)), half(65504.0))) * _1293, _1543 * fma(half(-float(_1770)), _1361, half(1.0)), _1543 * (min(min((_1796 * _1796) * half(0.3183098733425140380859375), half(65504.0)) * (half(0.25) / max(_1525 * _1525, half(6.103515625e-05))), half(65504.0)) * (_1770 * _1361))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1697 * _2148)) * min(min((_2092 * _2092) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1971, _1662, _1235 * sqrt(fma(_1971 * _1971, _1658, _1652))), half(65504.0)), half(65504.0))) * _1293, _1997 * fma(half(-float(_2224)), _1361, half(1.0)), _1997 * (min(min((_2250 * _2250) * half(0.3183098733425140380859375), half(65504.0)) * (half(0.25) / max(_1979 * _1979, half(6.103515625e-05))), half(65504.0)) * (_2224 * _1361))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2282, half(1.0)));
    return out;
}

