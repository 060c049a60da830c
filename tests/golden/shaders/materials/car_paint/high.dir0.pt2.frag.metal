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
    half3 _979 = normalize(half3(in.v_normal));
    float3 _985 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1268 = max(dot(_979, half3(_985)), half(9.9999997473787516355514526367188e-05));
    half3 _1272 = reflect(-half3(_985), _979);
    float4 _1307 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1268, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1326 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1307).y) - half(1.0)));
    float4 _1336 = facet_environment.sample(facet_environmentSmplr, float3(_1272), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1383 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1389 = half(1.0) - _1268;
    half _1392 = _1389 * _1389;
    half _1396 = half(0.959999978542327880859375) * _1383;
    half _1403 = fma(half(0.039999999105930328369140625), _1383, _1396 * ((_1392 * _1392) * _1389));
    half _1366 = half(1.0) - _1403;
    half _1408 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1418 = facet_environment.sample(facet_environmentSmplr, float3(_1272), level(_1408 * (half(4.0) * (half(2.0) - _1408))));
    float3 _1455 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1458 = dot(_1455, _1455);
    float3 _1463 = _1455 * rsqrt(fast::max(_1458, 9.9999999392252902907785028219223e-09));
    float _1467 = _1458 * float(frame.punctualLights[0].positionFalloff.w);
    float _1472 = fast::clamp(fma(-_1467, _1467, 1.0), 0.0, 1.0);
    float _1491 = fast::clamp(fma(dot(-_1463, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1627 = fast::normalize(_985 + _1463);
    half _1560 = clamp(dot(_979, half3(_1463)), half(0.0), half(1.0));
    half _1564 = clamp(dot(_979, half3(_1627)), half(0.0), half(1.0));
    half _1568 = clamp(dot(half3(_1463), half3(_1627)), half(0.0), half(1.0));
    half _1667 = half(4096.0) * half(params.facet_alpha);
    half3 _1686 = cross(_979, half3(_1627)) * half(64.0);
    half _1688 = half(64.0) * half(params.facet_alpha);
    half _1690 = _1688 * _1564;
    half _1693 = dot(_1686, _1686);
    half _1673 = _1667 / fma(_1690, _1690, _1693);
    half _1705 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1711 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1715 = sqrt(fma(_1268 * _1268, _1711, _1705));
    half _1739 = half(1.0) - _1568;
    half _1742 = _1739 * _1739;
    half _1747 = (_1742 * _1742) * _1739;
    half3 _1750 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1586 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1472) * half(_1472)) / fast::max(_1458, 9.9999997473787516355514526367188e-05)) * half(_1491)) * half(_1491)), float3(65504.0))) * _1560;
    half _1787 = _1408 * _1408;
    half _1835 = half(64.0) * _1787;
    half _1837 = _1835 * _1564;
    half _1797 = half(12.56637096405029296875) * max(_1568 * _1568, half(6.103515625e-05));
    half _1799 = half(4096.0) * _1787;
    half _1803 = _1799 / (fma(_1837, _1837, _1693) * _1797);
    float3 _1924 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1927 = dot(_1924, _1924);
    float3 _1932 = _1924 * rsqrt(fast::max(_1927, 9.9999999392252902907785028219223e-09));
    float _1936 = _1927 * float(frame.punctualLights[1].positionFalloff.w);
    float _1941 = fast::clamp(fma(-_1936, _1936, 1.0), 0.0, 1.0);
    float _1960 = fast::clamp(fma(dot(-_1932, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2096 = fast::normalize(_985 + _1932);
    half _2029 = clamp(dot(_979, half3(_1932)), half(0.0), half(1.0));
    half _2033 = clamp(dot(_979, half3(_2096)), half(0.0), half(1.0));
    half _2037 = clamp(dot(half3(_1932), half3(_2096)), half(0.0), half(1.0));
    half3 _2155 = cross(_979, half3(_2096)) * half(64.0);
    half _2159 = _1688 * _2033;
    half _2162 = dot(_2155, _2155);
    half _2142 = _1667 / fma(_2159, _2159, _2162);
    half _2208 = half(1.0) - _2037;
    half _2211 = _2208 * _2208;
    half _2216 = (_2211 * _2211) * _2208;
    half3 _2055 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1941) * half(_1941)) / fast::max(_1927, 9.9999997473787516355514526367188e-05)) * half(_1960)) * half(_1960)), float3(65504.0))) * _2029;
    half _2306 = _1835 * _2033;
    half _2266 = half(12.56637096405029296875) * max(_2037 * _2037, half(6.103515625e-05));
    half _2272 = _1799 / (fma(_2306, _2306, _2162) * _2266);
    half3 _2357 = (mix(half4(_1336).xyz * (mix(half4(_1307).xxx, half4(_1307).yyy, half3(float3(params.facet_f0))) * _1326), half4(_1418).xyz, half3(_1403)) + min(fma(((half3(float3(params.facet_f0)) + (_1750 * _1747)) * min(min((_1673 * _1673) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1560, _1715, _1268 * sqrt(fma(_1560 * _1560, _1711, _1705))), half(65504.0)), half(65504.0))) * _1326, _1586 * _1366, _1586 * (min(_1803 * (_1803 * _1797), half(65504.0)) * fma(half(0.039999999105930328369140625), _1383, _1396 * _1747))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1750 * _2216)) * min(min((_2142 * _2142) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2029, _1715, _1268 * sqrt(fma(_2029 * _2029, _1711, _1705))), half(65504.0)), half(65504.0))) * _1326, _2055 * _1366, _2055 * (min(_2272 * (_2272 * _2266), half(65504.0)) * fma(half(0.039999999105930328369140625), _1383, _1396 * _2216))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2357, half(1.0)));
    return out;
}

