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
    float facet_clearCoat;
    float facet_clearCoatAlpha;
    float facet_clearCoatLod;
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
    half3 _841 = normalize(half3(in.v_normal));
    float3 _847 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1083 = max(dot(_841, half3(_847)), half(9.9999997473787516355514526367188e-05));
    half3 _1087 = reflect(-half3(_847), _841);
    float4 _1122 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1083, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1141 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1122).y) - half(1.0)));
    float4 _1151 = facet_environment.sample(facet_environmentSmplr, float3(_1087), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1198 = half(1.0) - _1083;
    half _1201 = _1198 * _1198;
    half _1208 = fma(half(0.959999978542327880859375), (_1201 * _1201) * _1198, half(0.039999999105930328369140625));
    half _1178 = fma(half(-float(_1208)), half(params.facet_clearCoat), half(1.0));
    float4 _1186 = facet_environment.sample(facet_environmentSmplr, float3(_1087), level(params.facet_clearCoatLod));
    half3 _889 = half4(frame.lightDirection).xyz;
    half3 _1335 = normalize(half3(_847) + _889);
    half _1268 = clamp(dot(_841, _889), half(0.0), half(1.0));
    half _1272 = clamp(dot(_841, _1335), half(0.0), half(1.0));
    half _1276 = clamp(dot(_889, _1335), half(0.0), half(1.0));
    half3 _1398 = cross(_841, _1335) * half(64.0);
    half _1400 = half(64.0) * half(params.facet_alpha);
    half _1402 = _1400 * _1272;
    half _1405 = dot(_1398, _1398);
    half _1378 = half(4096.0) * half(params.facet_alpha);
    half _1381 = half(6.283185482025146484375) * max(mix((half(2.0) * _1268) * _1083, _1268 + _1083, half(params.facet_alpha)), half(0.000244140625));
    half _1383 = _1378 / (fma(_1402, _1402, _1405) * _1381);
    half _1490 = half(64.0) * half(params.facet_clearCoatAlpha);
    half _1492 = _1490 * _1272;
    half _1444 = half(12.56637096405029296875) * max(_1276 * _1276, half(6.103515625e-05));
    half _1446 = half(4096.0) * half(params.facet_clearCoatAlpha);
    half _1450 = _1446 / (fma(_1492, _1492, _1405) * _1444);
    half _1460 = half(1.0) - _1276;
    half _1463 = _1460 * _1460;
    half _1468 = half(0.959999978542327880859375) * half(params.facet_clearCoat);
    float3 _1558 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1561 = dot(_1558, _1558);
    float3 _1566 = _1558 * rsqrt(fast::max(_1561, 9.9999999392252902907785028219223e-09));
    float _1570 = _1561 * float(frame.punctualLights[0].positionFalloff.w);
    float _1575 = fast::clamp(fma(-_1570, _1570, 1.0), 0.0, 1.0);
    float _1594 = fast::clamp(fma(dot(-_1566, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1729 = normalize(half3(_847) + half3(_1566));
    half _1662 = clamp(dot(_841, half3(_1566)), half(0.0), half(1.0));
    half _1666 = clamp(dot(_841, _1729), half(0.0), half(1.0));
    half _1670 = clamp(dot(half3(_1566), _1729), half(0.0), half(1.0));
    half3 _1792 = cross(_841, _1729) * half(64.0);
    half _1796 = _1400 * _1666;
    half _1799 = dot(_1792, _1792);
    half _1775 = half(6.283185482025146484375) * max(mix((half(2.0) * _1662) * _1083, _1662 + _1083, half(params.facet_alpha)), half(0.000244140625));
    half _1777 = _1378 / (fma(_1796, _1796, _1799) * _1775);
    half _1886 = _1490 * _1666;
    half _1838 = half(12.56637096405029296875) * max(_1670 * _1670, half(6.103515625e-05));
    half _1844 = _1446 / (fma(_1886, _1886, _1799) * _1838);
    half _1854 = half(1.0) - _1670;
    half _1857 = _1854 * _1854;
    half3 _1916 = (mix(half4(_1151).xyz * (mix(half4(_1122).xxx, half4(_1122).yyy, half3(float3(params.facet_f0))) * _1141), half4(_1186).xyz, half3(_1208 * half(params.facet_clearCoat))) + min(min((((half3(float3(params.facet_f0)) * min(_1383 * (_1383 * _1381), half(65504.0))) * _1141) * _1178) + half3(min(_1450 * (_1450 * _1444), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1468 * ((_1463 * _1463) * _1460))), half3(float3(65504.0))) * (half4(frame.lightColor).xyz * _1268), half3(float3(65504.0)))) + min(min((((half3(float3(params.facet_f0)) * min(_1777 * (_1777 * _1775), half(65504.0))) * _1141) * _1178) + half3(min(_1844 * (_1844 * _1838), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1468 * ((_1857 * _1857) * _1854))), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1575) * half(_1575)) / fast::max(_1561, 9.9999997473787516355514526367188e-05)) * half(_1594)) * half(_1594)), float3(65504.0))) * _1662), half3(float3(65504.0)));
    float3 _1952 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1955 = dot(_1952, _1952);
    float3 _1960 = _1952 * rsqrt(fast::max(_1955, 9.9999999392252902907785028219223e-09));
    float _1964 = _1955 * float(frame.punctualLights[1].positionFalloff.w);
    float _1969 = fast::clamp(fma(-_1964, _1964, 1.0), 0.0, 1.0);
    float _1988 = fast::clamp(fma(dot(-_1960, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _2123 = normalize(half3(_847) + half3(_1960));
    half _2056 = clamp(dot(_841, half3(_1960)), half(0.0), half(1.0));
    half _2060 = clamp(dot(_841, _2123), half(0.0), half(1.0));
    half _2064 = clamp(dot(half3(_1960), _2123), half(0.0), half(1.0));
    half3 _2186 = cross(_841, _2123) * half(64.0);
    half _2190 = _1400 * _2060;
    half _2193 = dot(_2186, _2186);
    half _2169 = half(6.283185482025146484375) * max(mix((half(2.0) * _2056) * _1083, _2056 + _1083, half(params.facet_alpha)), half(0.000244140625));
    half _2171 = _1378 / (fma(_2190, _2190, _2193) * _2169);
    half _2280 = _1490 * _2060;
    half _2232 = half(12.56637096405029296875) * max(_2064 * _2064, half(6.103515625e-05));
    half _2238 = _1446 / (fma(_2280, _2280, _2193) * _2232);
    half _2248 = half(1.0) - _2064;
    half _2251 = _2248 * _2248;
    half3 _2310 = _1916 + min(min((((half3(float3(params.facet_f0)) * min(_2171 * (_2171 * _2169), half(65504.0))) * _1141) * _1178) + half3(min(_2238 * (_2238 * _2232), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1468 * ((_2251 * _2251) * _2248))), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1969) * half(_1969)) / fast::max(_1955, 9.9999997473787516355514526367188e-05)) * half(_1988)) * half(_1988)), float3(65504.0))) * _2056), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2310, half(1.0)));
    return out;
}

