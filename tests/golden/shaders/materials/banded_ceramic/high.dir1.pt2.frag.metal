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
    float _994 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _1043 = _842.y;
    half _1048 = _842.z;
    half _1053 = _842.x;
    half3 _1121 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1043)) + (half4(frame.sh[2]).xyz * _1048)) + (half4(frame.sh[3]).xyz * _1053)) + (((((half4(frame.sh[4]).xyz * (_1053 * _1043)) + (half4(frame.sh[5]).xyz * (_1043 * _1048))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1048, _1048, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1053 * _1048))) + (half4(frame.sh[8]).xyz * fma(_1053, _1053, half(-float(_1043 * _1043))))), half3(float3(0.0)));
    half3 _1144 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_994))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1219 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _994)), half(0.0), half(1.0));
    half3 _1227 = half3((half(0.1599999964237213134765625) * _1219) * _1219);
    half _1236 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _994)), half(0.08900000154972076416015625), half(1.0));
    half _1179 = max(dot(_842, half3(_848)), half(9.9999997473787516355514526367188e-05));
    float4 _1243 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1179, _1236)), level(0.0));
    half3 _1262 = half3(float3(1.0)) + (_1227 * ((half(1.0) / half4(_1243).y) - half(1.0)));
    float4 _1269 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_848), _842)), level(_1236 * half(4.0)));
    half _1408 = _1236 * _1236;
    float3 _1420 = fast::normalize(_848 + frame.lightDirection.xyz);
    half _1329 = clamp(dot(_842, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1460 = cross(_842, half3(_1420));
    half _1463 = clamp(dot(_842, half3(_1420)), half(0.0), half(1.0)) * _1408;
    half _1472 = _1408 / fma(_1463, _1463, dot(_1460, _1460));
    half _1486 = _1408 * _1408;
    half _1492 = fma(half(-float(_1408)), _1408, half(1.0));
    half _1496 = sqrt(fma(_1179 * _1179, _1492, _1486));
    half _1520 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1420)), half(0.0), half(1.0));
    half _1523 = _1520 * _1520;
    half3 _1531 = half3(float3(1.0)) - _1227;
    half3 _1360 = _1144 * half(0.3183098733425140380859375);
    float3 _1589 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1592 = dot(_1589, _1589);
    float3 _1597 = _1589 * rsqrt(fast::max(_1592, 9.9999999392252902907785028219223e-09));
    float _1601 = _1592 * float(frame.punctualLights[0].positionFalloff.w);
    float _1606 = fast::clamp(fma(-_1601, _1601, 1.0), 0.0, 1.0);
    float _1625 = fast::clamp(fma(dot(-_1597, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1779 = fast::normalize(_848 + _1597);
    half _1688 = clamp(dot(_842, half3(_1597)), half(0.0), half(1.0));
    half3 _1819 = cross(_842, half3(_1779));
    half _1822 = clamp(dot(_842, half3(_1779)), half(0.0), half(1.0)) * _1408;
    half _1831 = _1408 / fma(_1822, _1822, dot(_1819, _1819));
    half _1879 = half(1.0) - clamp(dot(half3(_1597), half3(_1779)), half(0.0), half(1.0));
    half _1882 = _1879 * _1879;
    float3 _1948 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1951 = dot(_1948, _1948);
    float3 _1956 = _1948 * rsqrt(fast::max(_1951, 9.9999999392252902907785028219223e-09));
    float _1960 = _1951 * float(frame.punctualLights[1].positionFalloff.w);
    float _1965 = fast::clamp(fma(-_1960, _1960, 1.0), 0.0, 1.0);
    float _1984 = fast::clamp(fma(dot(-_1956, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2138 = fast::normalize(_848 + _1956);
    half _2047 = clamp(dot(_842, half3(_1956)), half(0.0), half(1.0));
    half3 _2178 = cross(_842, half3(_2138));
    half _2181 = clamp(dot(_842, half3(_2138)), half(0.0), half(1.0)) * _1408;
    half _2190 = _1408 / fma(_2181, _2181, dot(_2178, _2178));
    half _2238 = half(1.0) - clamp(dot(half3(_1956), half3(_2138)), half(0.0), half(1.0));
    half _2241 = _2238 * _2238;
    half3 _2271 = ((fma(_1144, _1121, half4(_1269).xyz * (mix(half4(_1243).xxx, half4(_1243).yyy, _1227) * _1262)) + min(fma((_1227 + (_1531 * ((_1523 * _1523) * _1520))) * min(min((_1472 * _1472) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1329, _1496, _1179 * sqrt(fma(_1329 * _1329, _1492, _1486))), half(65504.0)), half(65504.0)), _1262, _1360) * (half4(frame.lightColor).xyz * _1329), half3(float3(65504.0)))) + min(fma((_1227 + (_1531 * ((_1882 * _1882) * _1879))) * min(min((_1831 * _1831) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1688, _1496, _1179 * sqrt(fma(_1688 * _1688, _1492, _1486))), half(65504.0)), half(65504.0)), _1262, _1360) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1606) * half(_1606)) / fast::max(_1592, 9.9999997473787516355514526367188e-05)) * half(_1625)) * half(_1625)), float3(65504.0))) * _1688), half3(float3(65504.0)))) + min(fma((_1227 + (_1531 * ((_2241 * _2241) * _2238))) * min(min((_2190 * _2190) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2047, _1496, _1179 * sqrt(fma(_2047 * _2047, _1492, _1486))), half(65504.0)), half(65504.0)), _1262, _1360) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1965) * half(_1965)) / fast::max(_1951, 9.9999997473787516355514526367188e-05)) * half(_1984)) * half(_1984)), float3(65504.0))) * _2047), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2271, half(1.0)));
    return out;
}

