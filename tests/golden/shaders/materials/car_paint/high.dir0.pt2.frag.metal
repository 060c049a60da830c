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
    half3 _972 = normalize(half3(in.v_normal));
    float3 _978 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1261 = max(dot(_972, half3(_978)), half(9.9999997473787516355514526367188e-05));
    half3 _1265 = reflect(-half3(_978), _972);
    float4 _1300 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1261, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1319 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1300).y) - half(1.0)));
    float4 _1326 = facet_environment.sample(facet_environmentSmplr, float3(_1265), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1374 = half(1.0) - _1261;
    half _1377 = _1374 * _1374;
    half _1384 = fma(half(0.959999978542327880859375), (_1377 * _1377) * _1374, half(0.039999999105930328369140625));
    half _1389 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1356 = fma(half(-float(_1384)), _1389, half(1.0));
    half _1394 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1401 = facet_environment.sample(facet_environmentSmplr, float3(_1265), level(_1394 * half(4.0)));
    float3 _1438 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1441 = dot(_1438, _1438);
    float3 _1446 = _1438 * rsqrt(fast::max(_1441, 9.9999999392252902907785028219223e-09));
    float _1450 = _1441 * float(frame.punctualLights[0].positionFalloff.w);
    float _1455 = fast::clamp(fma(-_1450, _1450, 1.0), 0.0, 1.0);
    float _1474 = fast::clamp(fma(dot(-_1446, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1610 = fast::normalize(_978 + _1446);
    half _1543 = clamp(dot(_972, half3(_1446)), half(0.0), half(1.0));
    half _1547 = clamp(dot(_972, half3(_1610)), half(0.0), half(1.0));
    half _1551 = clamp(dot(half3(_1446), half3(_1610)), half(0.0), half(1.0));
    half _1651 = half(4096.0) * half(params.facet_alpha);
    half3 _1671 = cross(_972, half3(_1610)) * half(64.0);
    half _1674 = half(64.0) * half(params.facet_alpha);
    half _1675 = _1547 * _1674;
    half _1678 = dot(_1671, _1671);
    half _1657 = _1651 / fma(_1675, _1675, _1678);
    half _1690 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1696 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1700 = sqrt(fma(_1261 * _1261, _1696, _1690));
    half _1724 = half(1.0) - _1551;
    half _1727 = _1724 * _1724;
    half _1732 = (_1727 * _1727) * _1724;
    half3 _1735 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1569 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1455) * half(_1455)) / fast::max(_1441, 9.9999997473787516355514526367188e-05)) * half(_1474)) * half(_1474)), float3(65504.0))) * _1543;
    half _1771 = _1394 * _1394;
    half _1821 = half(64.0) * _1771;
    half _1822 = _1547 * _1821;
    half _1781 = half(12.56637096405029296875) * max(_1551 * _1551, half(6.103515625e-05));
    half _1783 = half(4096.0) * _1771;
    half _1787 = _1783 / (fma(_1822, _1822, _1678) * _1781);
    float3 _1905 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1908 = dot(_1905, _1905);
    float3 _1913 = _1905 * rsqrt(fast::max(_1908, 9.9999999392252902907785028219223e-09));
    float _1917 = _1908 * float(frame.punctualLights[1].positionFalloff.w);
    float _1922 = fast::clamp(fma(-_1917, _1917, 1.0), 0.0, 1.0);
    float _1941 = fast::clamp(fma(dot(-_1913, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2077 = fast::normalize(_978 + _1913);
    half _2010 = clamp(dot(_972, half3(_1913)), half(0.0), half(1.0));
    half _2014 = clamp(dot(_972, half3(_2077)), half(0.0), half(1.0));
    half _2018 = clamp(dot(half3(_1913), half3(_2077)), half(0.0), half(1.0));
    half3 _2138 = cross(_972, half3(_2077)) * half(64.0);
    half _2142 = _2014 * _1674;
    half _2145 = dot(_2138, _2138);
    half _2124 = _1651 / fma(_2142, _2142, _2145);
    half _2191 = half(1.0) - _2018;
    half _2194 = _2191 * _2191;
    half _2199 = (_2194 * _2194) * _2191;
    half3 _2036 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1922) * half(_1922)) / fast::max(_1908, 9.9999997473787516355514526367188e-05)) * half(_1941)) * half(_1941)), float3(65504.0))) * _2010;
    half _2289 = _2014 * _1821;
    half _2248 = half(12.56637096405029296875) * max(_2018 * _2018, half(6.103515625e-05));
    half _2254 = _1783 / (fma(_2289, _2289, _2145) * _2248);
    half3 _2336 = (mix(half4(_1326).xyz * (mix(half4(_1300).xxx, half4(_1300).yyy, half3(float3(params.facet_f0))) * _1319), half4(_1401).xyz, half3(_1384 * _1389)) + min(fma(((half3(float3(params.facet_f0)) + (_1735 * _1732)) * min(min((_1657 * _1657) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1543, _1700, _1261 * sqrt(fma(_1543 * _1543, _1696, _1690))), half(65504.0)), half(65504.0))) * _1319, _1569 * _1356, _1569 * (min(_1787 * (_1787 * _1781), half(65504.0)) * (fma(half(0.959999978542327880859375), _1732, half(0.039999999105930328369140625)) * _1389))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1735 * _2199)) * min(min((_2124 * _2124) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2010, _1700, _1261 * sqrt(fma(_2010 * _2010, _1696, _1690))), half(65504.0)), half(65504.0))) * _1319, _2036 * _1356, _2036 * (min(_2254 * (_2254 * _2248), half(65504.0)) * (fma(half(0.959999978542327880859375), _2199, half(0.039999999105930328369140625)) * _1389))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2336, half(1.0)));
    return out;
}

