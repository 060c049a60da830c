#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 glazeColor;
    packed_float3 clayColor;
    float glazeRoughness;
    float clayRoughness;
    float bandsPerUnit;
    float bandSharpness;
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
    half3 _842 = normalize(half3(in.v_normal));
    float3 _848 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _991 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _1040 = _842.y;
    half _1045 = _842.z;
    half _1050 = _842.x;
    half3 _1118 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1040)) + (half4(frame.sh[2]).xyz * _1045)) + (half4(frame.sh[3]).xyz * _1050)) + (((((half4(frame.sh[4]).xyz * (_1050 * _1040)) + (half4(frame.sh[5]).xyz * (_1040 * _1045))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1045, _1045, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1050 * _1045))) + (half4(frame.sh[8]).xyz * fma(_1050, _1050, half(-float(_1040 * _1040))))), half3(float3(0.0)));
    half3 _1141 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_991))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1216 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _991)), half(0.0), half(1.0));
    half3 _1224 = half3((half(0.1599999964237213134765625) * _1216) * _1216);
    half _1233 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _991)), half(0.08900000154972076416015625), half(1.0));
    half _1176 = max(dot(_842, half3(_848)), half(9.9999997473787516355514526367188e-05));
    float4 _1240 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1176, _1233)), level(0.0));
    half3 _1259 = half3(float3(1.0)) + (_1224 * ((half(1.0) / half4(_1240).y) - half(1.0)));
    float4 _1266 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_848), _842)), level(_1233 * half(4.0)));
    half _1405 = _1233 * _1233;
    float3 _1417 = fast::normalize(_848 + frame.lightDirection.xyz);
    half _1326 = clamp(dot(_842, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1457 = cross(_842, half3(_1417));
    half _1460 = clamp(dot(_842, half3(_1417)), half(0.0), half(1.0)) * _1405;
    half _1469 = _1405 / fma(_1460, _1460, dot(_1457, _1457));
    half _1483 = _1405 * _1405;
    half _1489 = fma(half(-float(_1405)), _1405, half(1.0));
    half _1493 = sqrt(fma(_1176 * _1176, _1489, _1483));
    half _1517 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1417)), half(0.0), half(1.0));
    half _1520 = _1517 * _1517;
    half3 _1528 = half3(float3(1.0)) - _1224;
    half3 _1357 = _1141 * half(0.3183098733425140380859375);
    float3 _1586 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1589 = dot(_1586, _1586);
    float3 _1594 = _1586 * rsqrt(fast::max(_1589, 9.9999999392252902907785028219223e-09));
    float _1598 = _1589 * float(frame.punctualLights[0].positionFalloff.w);
    float _1603 = fast::clamp(fma(-_1598, _1598, 1.0), 0.0, 1.0);
    float _1622 = fast::clamp(fma(dot(-_1594, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1776 = fast::normalize(_848 + _1594);
    half _1685 = clamp(dot(_842, half3(_1594)), half(0.0), half(1.0));
    half3 _1816 = cross(_842, half3(_1776));
    half _1819 = clamp(dot(_842, half3(_1776)), half(0.0), half(1.0)) * _1405;
    half _1828 = _1405 / fma(_1819, _1819, dot(_1816, _1816));
    half _1876 = half(1.0) - clamp(dot(half3(_1594), half3(_1776)), half(0.0), half(1.0));
    half _1879 = _1876 * _1876;
    float3 _1945 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1948 = dot(_1945, _1945);
    float3 _1953 = _1945 * rsqrt(fast::max(_1948, 9.9999999392252902907785028219223e-09));
    float _1957 = _1948 * float(frame.punctualLights[1].positionFalloff.w);
    float _1962 = fast::clamp(fma(-_1957, _1957, 1.0), 0.0, 1.0);
    float _1981 = fast::clamp(fma(dot(-_1953, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2135 = fast::normalize(_848 + _1953);
    half _2044 = clamp(dot(_842, half3(_1953)), half(0.0), half(1.0));
    half3 _2175 = cross(_842, half3(_2135));
    half _2178 = clamp(dot(_842, half3(_2135)), half(0.0), half(1.0)) * _1405;
    half _2187 = _1405 / fma(_2178, _2178, dot(_2175, _2175));
    half _2235 = half(1.0) - clamp(dot(half3(_1953), half3(_2135)), half(0.0), half(1.0));
    half _2238 = _2235 * _2235;
    half3 _2268 = ((fma(_1141, _1118, half4(_1266).xyz * (mix(half4(_1240).xxx, half4(_1240).yyy, _1224) * _1259)) + min(fma((_1224 + (_1528 * ((_1520 * _1520) * _1517))) * min(min((_1469 * _1469) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1326, _1493, _1176 * sqrt(fma(_1326 * _1326, _1489, _1483))), half(65504.0)), half(65504.0)), _1259, _1357) * (half4(frame.lightColor).xyz * _1326), half3(float3(65504.0)))) + min(fma((_1224 + (_1528 * ((_1879 * _1879) * _1876))) * min(min((_1828 * _1828) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1685, _1493, _1176 * sqrt(fma(_1685 * _1685, _1489, _1483))), half(65504.0)), half(65504.0)), _1259, _1357) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1603) * half(_1603)) / fast::max(_1589, 9.9999997473787516355514526367188e-05)) * half(_1622)) * half(_1622)), float3(65504.0))) * _1685), half3(float3(65504.0)))) + min(fma((_1224 + (_1528 * ((_2238 * _2238) * _2235))) * min(min((_2187 * _2187) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2044, _1493, _1176 * sqrt(fma(_2044 * _2044, _1489, _1483))), half(65504.0)), half(65504.0)), _1259, _1357) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1962) * half(_1962)) / fast::max(_1948, 9.9999997473787516355514526367188e-05)) * half(_1981)) * half(_1981)), float3(65504.0))) * _2044), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2268, half(1.0)));
    return out;
}

