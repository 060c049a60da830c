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
    half _1274 = max(dot(_964, half3(_970)), half(9.9999997473787516355514526367188e-05));
    half3 _1278 = reflect(-half3(_970), _964);
    float4 _1313 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1274, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1332 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1313).y) - half(1.0)));
    float4 _1344 = facet_environment.sample(facet_environmentSmplr, float3(_1278), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1392 = half(1.0) - _1274;
    half _1395 = _1392 * _1392;
    half _1402 = fma(half(0.959999978542327880859375), (_1395 * _1395) * _1392, half(0.039999999105930328369140625));
    half _1407 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1374 = fma(half(-float(_1402)), _1407, half(1.0));
    half _1412 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1424 = facet_environment.sample(facet_environmentSmplr, float3(_1278), level(_1412 * (half(4.0) * (half(2.0) - _1412))));
    float3 _1549 = fast::normalize(_970 + frame.lightDirection.xyz);
    half _1482 = clamp(dot(_964, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1486 = clamp(dot(_964, half3(_1549)), half(0.0), half(1.0));
    half _1490 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1549)), half(0.0), half(1.0));
    half3 _1589 = cross(_964, half3(_1549));
    half _1592 = _1486 * half(params.facet_alpha);
    half _1596 = dot(_1589, _1589);
    half _1601 = half(params.facet_alpha) / fma(_1592, _1592, _1596);
    half _1615 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1621 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1625 = sqrt(fma(_1274 * _1274, _1621, _1615));
    half _1649 = half(1.0) - _1490;
    half _1652 = _1649 * _1649;
    half _1657 = (_1652 * _1652) * _1649;
    half3 _1660 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1508 = half4(frame.lightColor).xyz * _1482;
    half _1694 = _1412 * _1412;
    half _1700 = _1486 * _1694;
    half _1711 = max(_1490 * _1490, half(6.103515625e-05));
    half _1714 = half(2048.0) * _1694;
    half _1719 = _1714 / (fma(_1700, _1700, _1596) * (_1711 * half(25735.927734375)));
    float3 _1818 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1821 = dot(_1818, _1818);
    float3 _1826 = _1818 * rsqrt(fast::max(_1821, 9.9999999392252902907785028219223e-09));
    float _1830 = _1821 * float(frame.punctualLights[0].positionFalloff.w);
    float _1835 = fast::clamp(fma(-_1830, _1830, 1.0), 0.0, 1.0);
    float _1854 = fast::clamp(fma(dot(-_1826, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1990 = fast::normalize(_970 + _1826);
    half _1923 = clamp(dot(_964, half3(_1826)), half(0.0), half(1.0));
    half _1927 = clamp(dot(_964, half3(_1990)), half(0.0), half(1.0));
    half _1931 = clamp(dot(half3(_1826), half3(_1990)), half(0.0), half(1.0));
    half3 _2030 = cross(_964, half3(_1990));
    half _2033 = _1927 * half(params.facet_alpha);
    half _2037 = dot(_2030, _2030);
    half _2042 = half(params.facet_alpha) / fma(_2033, _2033, _2037);
    half _2090 = half(1.0) - _1931;
    half _2093 = _2090 * _2090;
    half _2098 = (_2093 * _2093) * _2090;
    half3 _1949 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1835) * half(_1835)) / fast::max(_1821, 9.9999997473787516355514526367188e-05)) * half(_1854)) * half(_1854)), float3(65504.0))) * _1923;
    half _2141 = _1927 * _1694;
    half _2152 = max(_1931 * _1931, half(6.103515625e-05));
    half _2160 = _1714 / (fma(_2141, _2141, _2037) * (_2152 * half(25735.927734375)));
    half3 _2223 = (mix(half4(_1344).xyz * (mix(half4(_1313).xxx, half4(_1313).yyy, half3(float3(params.facet_f0))) * _1332), half4(_1424).xyz, half3(_1402 * _1407)) + min(fma(((half3(float3(params.facet_f0)) + (_1660 * _1657)) * min(min((_1601 * _1601) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1482, _1625, _1274 * sqrt(fma(_1482 * _1482, _1621, _1615))), half(65504.0)), half(65504.0))) * _1332, _1508 * _1374, _1508 * (min(_1719 * (_1719 * (half(12.56637096405029296875) * _1711)), half(65504.0)) * (fma(half(0.959999978542327880859375), _1657, half(0.039999999105930328369140625)) * _1407))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1660 * _2098)) * min(min((_2042 * _2042) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1923, _1625, _1274 * sqrt(fma(_1923 * _1923, _1621, _1615))), half(65504.0)), half(65504.0))) * _1332, _1949 * _1374, _1949 * (min(_2160 * (_2160 * (half(12.56637096405029296875) * _2152)), half(65504.0)) * (fma(half(0.959999978542327880859375), _2098, half(0.039999999105930328369140625)) * _1407))), half3(float3(65504.0)));
    float3 _2259 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2262 = dot(_2259, _2259);
    float3 _2267 = _2259 * rsqrt(fast::max(_2262, 9.9999999392252902907785028219223e-09));
    float _2271 = _2262 * float(frame.punctualLights[1].positionFalloff.w);
    float _2276 = fast::clamp(fma(-_2271, _2271, 1.0), 0.0, 1.0);
    float _2295 = fast::clamp(fma(dot(-_2267, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2431 = fast::normalize(_970 + _2267);
    half _2364 = clamp(dot(_964, half3(_2267)), half(0.0), half(1.0));
    half _2368 = clamp(dot(_964, half3(_2431)), half(0.0), half(1.0));
    half _2372 = clamp(dot(half3(_2267), half3(_2431)), half(0.0), half(1.0));
    half3 _2471 = cross(_964, half3(_2431));
    half _2474 = _2368 * half(params.facet_alpha);
    half _2478 = dot(_2471, _2471);
    half _2483 = half(params.facet_alpha) / fma(_2474, _2474, _2478);
    half _2531 = half(1.0) - _2372;
    half _2534 = _2531 * _2531;
    half _2539 = (_2534 * _2534) * _2531;
    half3 _2390 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2276) * half(_2276)) / fast::max(_2262, 9.9999997473787516355514526367188e-05)) * half(_2295)) * half(_2295)), float3(65504.0))) * _2364;
    half _2582 = _2368 * _1694;
    half _2593 = max(_2372 * _2372, half(6.103515625e-05));
    half _2601 = _1714 / (fma(_2582, _2582, _2478) * (_2593 * half(25735.927734375)));
    out.fragColor = float4(half4(_2223 + min(fma(((half3(float3(params.facet_f0)) + (_1660 * _2539)) * min(min((_2483 * _2483) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2364, _1625, _1274 * sqrt(fma(_2364 * _2364, _1621, _1615))), half(65504.0)), half(65504.0))) * _1332, _2390 * _1374, _2390 * (min(_2601 * (_2601 * (half(12.56637096405029296875) * _2593)), half(65504.0)) * (fma(half(0.959999978542327880859375), _2539, half(0.039999999105930328369140625)) * _1407))), half3(float3(65504.0))), half(1.0)));
    return out;
}

