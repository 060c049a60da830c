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
    float4 _1329 = facet_environment.sample(facet_environmentSmplr, float3(_1265), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1377 = half(1.0) - _1261;
    half _1380 = _1377 * _1377;
    half _1387 = fma(half(0.959999978542327880859375), (_1380 * _1380) * _1377, half(0.039999999105930328369140625));
    half _1392 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1359 = fma(half(-float(_1387)), _1392, half(1.0));
    half _1397 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1407 = facet_environment.sample(facet_environmentSmplr, float3(_1265), level(_1397 * (half(4.0) * (half(2.0) - _1397))));
    float3 _1444 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1447 = dot(_1444, _1444);
    float3 _1452 = _1444 * rsqrt(fast::max(_1447, 9.9999999392252902907785028219223e-09));
    float _1456 = _1447 * float(frame.punctualLights[0].positionFalloff.w);
    float _1461 = fast::clamp(fma(-_1456, _1456, 1.0), 0.0, 1.0);
    float _1480 = fast::clamp(fma(dot(-_1452, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1616 = fast::normalize(_978 + _1452);
    half _1549 = clamp(dot(_972, half3(_1452)), half(0.0), half(1.0));
    half _1553 = clamp(dot(_972, half3(_1616)), half(0.0), half(1.0));
    half _1557 = clamp(dot(half3(_1452), half3(_1616)), half(0.0), half(1.0));
    half _1656 = half(4096.0) * half(params.facet_alpha);
    half3 _1673 = cross(_972, half3(_1616));
    half _1677 = _1673.x;
    half4 _1681 = half4(_1677, _1673.yz, half(params.facet_alpha) * _1553) * half(64.0);
    half _1662 = _1656 / dot(_1681, _1681);
    half _1692 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1698 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1702 = sqrt(fma(_1261 * _1261, _1698, _1692));
    half _1726 = half(1.0) - _1557;
    half _1729 = _1726 * _1726;
    half _1734 = (_1729 * _1729) * _1726;
    half3 _1737 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1575 = half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1461) * half(_1461)) / fast::max(_1447, 9.9999997473787516355514526367188e-05)) * half(_1480)) * half(_1480)), float3(65504.0))) * _1549;
    half _1773 = _1397 * _1397;
    half4 _1826 = half4(_1677, _1673.yz, _1773 * _1553) * half(64.0);
    half _1783 = half(12.56637096405029296875) * max(_1557 * _1557, half(6.103515625e-05));
    half _1785 = half(4096.0) * _1773;
    half _1789 = _1785 / (dot(_1826, _1826) * _1783);
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
    half3 _2134 = cross(_972, half3(_2077));
    half _2138 = _2134.x;
    half4 _2142 = half4(_2138, _2134.yz, half(params.facet_alpha) * _2014) * half(64.0);
    half _2123 = _1656 / dot(_2142, _2142);
    half _2187 = half(1.0) - _2018;
    half _2190 = _2187 * _2187;
    half _2195 = (_2190 * _2190) * _2187;
    half3 _2036 = half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1922) * half(_1922)) / fast::max(_1908, 9.9999997473787516355514526367188e-05)) * half(_1941)) * half(_1941)), float3(65504.0))) * _2010;
    half4 _2287 = half4(_2138, _2134.yz, _1773 * _2014) * half(64.0);
    half _2244 = half(12.56637096405029296875) * max(_2018 * _2018, half(6.103515625e-05));
    half _2250 = _1785 / (dot(_2287, _2287) * _2244);
    half3 _2330 = (mix(half4(_1329).xyz * (mix(half4(_1300).xxx, half4(_1300).yyy, half3(float3(params.facet_f0))) * _1319), half4(_1407).xyz, half3(_1387 * _1392)) + min(fma(((half3(float3(params.facet_f0)) + (_1737 * _1734)) * min(min((_1662 * _1662) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1549, _1702, _1261 * sqrt(fma(_1549 * _1549, _1698, _1692))), half(65504.0)), half(65504.0))) * _1319, _1575 * _1359, _1575 * (min(_1789 * (_1789 * _1783), half(65504.0)) * (fma(half(0.959999978542327880859375), _1734, half(0.039999999105930328369140625)) * _1392))), half3(float3(65504.0)))) + min(fma(((half3(float3(params.facet_f0)) + (_1737 * _2195)) * min(min((_2123 * _2123) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2010, _1702, _1261 * sqrt(fma(_2010 * _2010, _1698, _1692))), half(65504.0)), half(65504.0))) * _1319, _2036 * _1359, _2036 * (min(_2250 * (_2250 * _2244), half(65504.0)) * (fma(half(0.959999978542327880859375), _2195, half(0.039999999105930328369140625)) * _1392))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2330, half(1.0)));
    return out;
}

