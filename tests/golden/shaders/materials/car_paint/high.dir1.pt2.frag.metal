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
    half _1278 = max(dot(_968, half3(_974)), half(9.9999997473787516355514526367188e-05));
    half3 _1282 = reflect(-half3(_974), _968);
    float4 _1317 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1278, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1336 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1317).y) - half(1.0)));
    float4 _1343 = facet_environment.sample(facet_environmentSmplr, float3(_1282), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1391 = half(1.0) - _1278;
    half _1394 = _1391 * _1391;
    half _1401 = fma(half(0.959999978542327880859375), (_1394 * _1394) * _1391, half(0.039999999105930328369140625));
    half _1406 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1373 = fma(half(-float(_1401)), _1406, half(1.0));
    half _1411 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1418 = facet_environment.sample(facet_environmentSmplr, float3(_1282), level(_1411 * half(4.0)));
    float3 _1543 = fast::normalize(_974 + frame.lightDirection.xyz);
    half _1476 = clamp(dot(_968, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1480 = clamp(dot(_968, half3(_1543)), half(0.0), half(1.0));
    half _1484 = clamp(dot(half3(frame.lightDirection.xyz), half3(_1543)), half(0.0), half(1.0));
    half _1583 = half(4096.0) * half(params.facet_alpha);
    half3 _1600 = cross(_968, half3(_1543));
    half _1604 = _1600.x;
    half4 _1608 = half4(_1604, _1600.yz, half(params.facet_alpha) * _1480) * half(64.0);
    half _1589 = _1583 / dot(_1608, _1608);
    half _1619 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1625 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1629 = sqrt(fma(_1278 * _1278, _1625, _1619));
    half _1653 = half(1.0) - _1484;
    half _1656 = _1653 * _1653;
    half _1661 = (_1656 * _1656) * _1653;
    half3 _1664 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1502 = half4(frame.lightColor).xyz * _1476;
    half _1700 = _1411 * _1411;
    half4 _1753 = half4(_1604, _1600.yz, _1700 * _1480) * half(64.0);
    half _1710 = half(12.56637096405029296875) * max(_1484 * _1484, half(6.103515625e-05));
    half _1712 = half(4096.0) * _1700;
    half _1716 = _1712 / (dot(_1753, _1753) * _1710);
    float3 _1832 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1835 = dot(_1832, _1832);
    float3 _1840 = _1832 * rsqrt(fast::max(_1835, 9.9999999392252902907785028219223e-09));
    float _1844 = _1835 * float(frame.punctualLights[0].positionFalloff.w);
    float _1849 = fast::clamp(fma(-_1844, _1844, 1.0), 0.0, 1.0);
    float _1868 = fast::clamp(fma(dot(-_1840, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2004 = fast::normalize(_974 + _1840);
    half _1937 = clamp(dot(_968, half3(_1840)), half(0.0), half(1.0));
    half _1941 = clamp(dot(_968, half3(_2004)), half(0.0), half(1.0));
    half _1945 = clamp(dot(half3(_1840), half3(_2004)), half(0.0), half(1.0));
    half3 _2061 = cross(_968, half3(_2004));
    half _2065 = _2061.x;
    half4 _2069 = half4(_2065, _2061.yz, half(params.facet_alpha) * _1941) * half(64.0);
    half _2050 = _1583 / dot(_2069, _2069);
    half _2114 = half(1.0) - _1945;
    half _2117 = _2114 * _2114;
    half _2122 = (_2117 * _2117) * _2114;
    half3 _1963 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1849) * half(_1849)) / fast::max(_1835, 9.9999997473787516355514526367188e-05)) * half(_1868)) * half(_1868)), float3(65504.0))) * _1937;
    half4 _2214 = half4(_2065, _2061.yz, _1700 * _1941) * half(64.0);
    half _2171 = half(12.56637096405029296875) * max(_1945 * _1945, half(6.103515625e-05));
    half _2177 = _1712 / (dot(_2214, _2214) * _2171);
    half3 _2257 = (mix(half4(_1343).xyz * (mix(half4(_1317).xxx, half4(_1317).yyy, half3(float3(params.facet_f0))) * _1336), half4(_1418).xyz, half3(_1401 * _1406)) + min(fma(((half3(float3(params.facet_f0)) + (_1664 * _1661)) * min(min((_1589 * _1589) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1476, _1629, _1278 * sqrt(fma(_1476 * _1476, _1625, _1619))), half(65504.0)), half(65504.0))) * _1336, _1502 * _1373, _1502 * (min(_1716 * (_1716 * _1710), half(65504.0)) * (fma(half(0.959999978542327880859375), _1661, half(0.039999999105930328369140625)) * _1406))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1664 * _2122)) * min(min((_2050 * _2050) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1937, _1629, _1278 * sqrt(fma(_1937 * _1937, _1625, _1619))), half(65504.0)), half(65504.0))) * _1336, _1963 * _1373, _1963 * (min(_2177 * (_2177 * _2171), half(65504.0)) * (fma(half(0.959999978542327880859375), _2122, half(0.039999999105930328369140625)) * _1406))), half3(float3(65504.0)));
    float3 _2293 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2296 = dot(_2293, _2293);
    float3 _2301 = _2293 * rsqrt(fast::max(_2296, 9.9999999392252902907785028219223e-09));
    float _2305 = _2296 * float(frame.punctualLights[1].positionFalloff.w);
    float _2310 = fast::clamp(fma(-_2305, _2305, 1.0), 0.0, 1.0);
    float _2329 = fast::clamp(fma(dot(-_2301, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2465 = fast::normalize(_974 + _2301);
    half _2398 = clamp(dot(_968, half3(_2301)), half(0.0), half(1.0));
    half _2402 = clamp(dot(_968, half3(_2465)), half(0.0), half(1.0));
    half _2406 = clamp(dot(half3(_2301), half3(_2465)), half(0.0), half(1.0));
    half3 _2522 = cross(_968, half3(_2465));
    half _2526 = _2522.x;
    half4 _2530 = half4(_2526, _2522.yz, half(params.facet_alpha) * _2402) * half(64.0);
    half _2511 = _1583 / dot(_2530, _2530);
    half _2575 = half(1.0) - _2406;
    half _2578 = _2575 * _2575;
    half _2583 = (_2578 * _2578) * _2575;
    half3 _2424 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2310) * half(_2310)) / fast::max(_2296, 9.9999997473787516355514526367188e-05)) * half(_2329)) * half(_2329)), float3(65504.0))) * _2398;
    half4 _2675 = half4(_2526, _2522.yz, _1700 * _2402) * half(64.0);
    half _2632 = half(12.56637096405029296875) * max(_2406 * _2406, half(6.103515625e-05));
    half _2638 = _1712 / (dot(_2675, _2675) * _2632);
    out.fragColor = float4(half4(_2257 + min(fma(((half3(float3(params.facet_f0)) + (_1664 * _2583)) * min(min((_2511 * _2511) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2398, _1629, _1278 * sqrt(fma(_2398 * _2398, _1625, _1619))), half(65504.0)), half(65504.0))) * _1336, _2424 * _1373, _2424 * (min(_2638 * (_2638 * _2632), half(65504.0)) * (fma(half(0.959999978542327880859375), _2583, half(0.039999999105930328369140625)) * _1406))), half3(float3(65504.0))), half(1.0)));
    return out;
}

