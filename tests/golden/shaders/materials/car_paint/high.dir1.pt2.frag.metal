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
    half3 _962 = normalize(half3(in.v_normal));
    float3 _968 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1272 = max(dot(_962, half3(_968)), half(9.9999997473787516355514526367188e-05));
    half3 _1276 = reflect(-half3(_968), _962);
    float4 _1311 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1272, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1330 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1311).y) - half(1.0)));
    float4 _1340 = facet_environment.sample(facet_environmentSmplr, float3(_1276), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1388 = half(1.0) - _1272;
    half _1391 = _1388 * _1388;
    half _1398 = fma(half(0.959999978542327880859375), (_1391 * _1391) * _1388, half(0.039999999105930328369140625));
    half _1403 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1370 = fma(half(-float(_1398)), _1403, half(1.0));
    half _1408 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1418 = facet_environment.sample(facet_environmentSmplr, float3(_1276), level(_1408 * (half(4.0) * (half(2.0) - _1408))));
    float3 _1543 = fast::normalize(_968 + frame.lightDirection.xyz);
    half _1476 = clamp(dot(_962, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1480 = clamp(dot(_962, half3(_1543)), half(0.0), half(1.0));
    half _1484 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1543)), half(0.0), half(1.0));
    half3 _1583 = cross(_962, half3(_1543));
    half _1586 = _1480 * half(params.facet_alpha);
    half _1590 = dot(_1583, _1583);
    half _1595 = half(params.facet_alpha) / fma(_1586, _1586, _1590);
    half _1609 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1615 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1619 = sqrt(fma(_1272 * _1272, _1615, _1609));
    half _1643 = half(1.0) - _1484;
    half _1646 = _1643 * _1643;
    half _1651 = (_1646 * _1646) * _1643;
    half3 _1654 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1502 = half4(frame.lightColor).xyz * _1476;
    half _1688 = _1408 * _1408;
    half _1694 = _1480 * _1688;
    half _1705 = max(_1484 * _1484, half(6.103515625e-05));
    half _1708 = half(2048.0) * _1688;
    half _1713 = _1708 / (fma(_1694, _1694, _1590) * (_1705 * half(25735.927734375)));
    float3 _1812 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1815 = dot(_1812, _1812);
    float3 _1820 = _1812 * rsqrt(fast::max(_1815, 9.9999999392252902907785028219223e-09));
    float _1824 = _1815 * float(frame.punctualLights[0].positionFalloff.w);
    float _1829 = fast::clamp(fma(-_1824, _1824, 1.0), 0.0, 1.0);
    float _1848 = fast::clamp(fma(dot(-_1820, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1984 = fast::normalize(_968 + _1820);
    half _1917 = clamp(dot(_962, half3(_1820)), half(0.0), half(1.0));
    half _1921 = clamp(dot(_962, half3(_1984)), half(0.0), half(1.0));
    half _1925 = clamp(dot(half3(_1820), half3(_1984)), half(0.0), half(1.0));
    half3 _2024 = cross(_962, half3(_1984));
    half _2027 = _1921 * half(params.facet_alpha);
    half _2031 = dot(_2024, _2024);
    half _2036 = half(params.facet_alpha) / fma(_2027, _2027, _2031);
    half _2084 = half(1.0) - _1925;
    half _2087 = _2084 * _2084;
    half _2092 = (_2087 * _2087) * _2084;
    half3 _1943 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1829) * half(_1829)) / fast::max(_1815, 9.9999997473787516355514526367188e-05)) * half(_1848)) * half(_1848)), float3(65504.0))) * _1917;
    half _2135 = _1921 * _1688;
    half _2146 = max(_1925 * _1925, half(6.103515625e-05));
    half _2154 = _1708 / (fma(_2135, _2135, _2031) * (_2146 * half(25735.927734375)));
    half3 _2217 = (mix(half4(_1340).xyz * (mix(half4(_1311).xxx, half4(_1311).yyy, half3(float3(params.facet_f0))) * _1330), half4(_1418).xyz, half3(_1398 * _1403)) + min(fma(((half3(float3(params.facet_f0)) + (_1654 * _1651)) * min(min((_1595 * _1595) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1476, _1619, _1272 * sqrt(fma(_1476 * _1476, _1615, _1609))), half(65504.0)), half(65504.0))) * _1330, _1502 * _1370, _1502 * (min(_1713 * (_1713 * (half(12.56637096405029296875) * _1705)), half(65504.0)) * (fma(half(0.959999978542327880859375), _1651, half(0.039999999105930328369140625)) * _1403))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1654 * _2092)) * min(min((_2036 * _2036) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1917, _1619, _1272 * sqrt(fma(_1917 * _1917, _1615, _1609))), half(65504.0)), half(65504.0))) * _1330, _1943 * _1370, _1943 * (min(_2154 * (_2154 * (half(12.56637096405029296875) * _2146)), half(65504.0)) * (fma(half(0.959999978542327880859375), _2092, half(0.039999999105930328369140625)) * _1403))), half3(float3(65504.0)));
    float3 _2253 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2256 = dot(_2253, _2253);
    float3 _2261 = _2253 * rsqrt(fast::max(_2256, 9.9999999392252902907785028219223e-09));
    float _2265 = _2256 * float(frame.punctualLights[1].positionFalloff.w);
    float _2270 = fast::clamp(fma(-_2265, _2265, 1.0), 0.0, 1.0);
    float _2289 = fast::clamp(fma(dot(-_2261, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2425 = fast::normalize(_968 + _2261);
    half _2358 = clamp(dot(_962, half3(_2261)), half(0.0), half(1.0));
    half _2362 = clamp(dot(_962, half3(_2425)), half(0.0), half(1.0));
    half _2366 = clamp(dot(half3(_2261), half3(_2425)), half(0.0), half(1.0));
    half3 _2465 = cross(_962, half3(_2425));
    half _2468 = _2362 * half(params.facet_alpha);
    half _2472 = dot(_2465, _2465);
    half _2477 = half(params.facet_alpha) / fma(_2468, _2468, _2472);
    half _2525 = half(1.0) - _2366;
    half _2528 = _2525 * _2525;
    half _2533 = (_2528 * _2528) * _2525;
    half3 _2384 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2270) * half(_2270)) / fast::max(_2256, 9.9999997473787516355514526367188e-05)) * half(_2289)) * half(_2289)), float3(65504.0))) * _2358;
    half _2576 = _2362 * _1688;
    half _2587 = max(_2366 * _2366, half(6.103515625e-05));
    half _2595 = _1708 / (fma(_2576, _2576, _2472) * (_2587 * half(25735.927734375)));
    out.fragColor = float4(half4(_2217 + min(fma(((half3(float3(params.facet_f0)) + (_1654 * _2533)) * min(min((_2477 * _2477) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2358, _1619, _1272 * sqrt(fma(_2358 * _2358, _1615, _1609))), half(65504.0)), half(65504.0))) * _1330, _2384 * _1370, _2384 * (min(_2595 * (_2595 * (half(12.56637096405029296875) * _2587)), half(65504.0)) * (fma(half(0.959999978542327880859375), _2533, half(0.039999999105930328369140625)) * _1403))), half3(float3(65504.0))), half(1.0)));
    return out;
}

