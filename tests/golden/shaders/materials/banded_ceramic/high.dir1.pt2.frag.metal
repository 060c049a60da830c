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
    half3 _848 = normalize(half3(in.v_normal));
    float3 _854 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _997 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _1046 = _848.y;
    half _1051 = _848.z;
    half _1056 = _848.x;
    half3 _1124 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1046)) + (half4(frame.sh[2]).xyz * _1051)) + (half4(frame.sh[3]).xyz * _1056)) + (((((half4(frame.sh[4]).xyz * (_1056 * _1046)) + (half4(frame.sh[5]).xyz * (_1046 * _1051))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1051, _1051, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1056 * _1051))) + (half4(frame.sh[8]).xyz * fma(_1056, _1056, half(-float(_1046 * _1046))))), half3(float3(0.0)));
    half3 _1147 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_997))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1222 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _997)), half(0.0), half(1.0));
    half3 _1230 = half3((half(0.1599999964237213134765625) * _1222) * _1222);
    half _1239 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _997)), half(0.08900000154972076416015625), half(1.0));
    half _1182 = max(dot(_848, half3(_854)), half(9.9999997473787516355514526367188e-05));
    float4 _1246 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1182, _1239)), level(0.0));
    half3 _1265 = half3(float3(1.0)) + (_1230 * ((half(1.0) / half4(_1246).y) - half(1.0)));
    float4 _1277 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_854), _848)), level(_1239 * (half(4.0) * (half(2.0) - _1239))));
    half _1416 = _1239 * _1239;
    float3 _1428 = fast::normalize(_854 + frame.lightDirection.xyz);
    half _1337 = clamp(dot(_848, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1468 = cross(_848, half3(_1428));
    half _1471 = clamp(dot(_848, half3(_1428)), half(0.0), half(1.0)) * _1416;
    half _1480 = _1416 / fma(_1471, _1471, dot(_1468, _1468));
    half _1494 = _1416 * _1416;
    half _1500 = fma(half(-float(_1416)), _1416, half(1.0));
    half _1504 = sqrt(fma(_1182 * _1182, _1500, _1494));
    half _1528 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1428)), half(0.0), half(1.0));
    half _1531 = _1528 * _1528;
    half3 _1539 = half3(float3(1.0)) - _1230;
    half3 _1368 = _1147 * half(0.3183098733425140380859375);
    float3 _1597 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1600 = dot(_1597, _1597);
    float3 _1605 = _1597 * rsqrt(fast::max(_1600, 9.9999999392252902907785028219223e-09));
    float _1609 = _1600 * float(frame.punctualLights[0].positionFalloff.w);
    float _1614 = fast::clamp(fma(-_1609, _1609, 1.0), 0.0, 1.0);
    float _1633 = fast::clamp(fma(dot(-_1605, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1787 = fast::normalize(_854 + _1605);
    half _1696 = clamp(dot(_848, half3(_1605)), half(0.0), half(1.0));
    half3 _1827 = cross(_848, half3(_1787));
    half _1830 = clamp(dot(_848, half3(_1787)), half(0.0), half(1.0)) * _1416;
    half _1839 = _1416 / fma(_1830, _1830, dot(_1827, _1827));
    half _1887 = half(1.0) - clamp(dot(half3(_1605), half3(_1787)), half(0.0), half(1.0));
    half _1890 = _1887 * _1887;
    float3 _1956 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1959 = dot(_1956, _1956);
    float3 _1964 = _1956 * rsqrt(fast::max(_1959, 9.9999999392252902907785028219223e-09));
    float _1968 = _1959 * float(frame.punctualLights[1].positionFalloff.w);
    float _1973 = fast::clamp(fma(-_1968, _1968, 1.0), 0.0, 1.0);
    float _1992 = fast::clamp(fma(dot(-_1964, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2146 = fast::normalize(_854 + _1964);
    half _2055 = clamp(dot(_848, half3(_1964)), half(0.0), half(1.0));
    half3 _2186 = cross(_848, half3(_2146));
    half _2189 = clamp(dot(_848, half3(_2146)), half(0.0), half(1.0)) * _1416;
    half _2198 = _1416 / fma(_2189, _2189, dot(_2186, _2186));
    half _2246 = half(1.0) - clamp(dot(half3(_1964), half3(_2146)), half(0.0), half(1.0));
    half _2249 = _2246 * _2246;
    half3 _2279 = ((fma(_1147, _1124, half4(_1277).xyz * (mix(half4(_1246).xxx, half4(_1246).yyy, _1230) * _1265)) + min(fma((_1230 + (_1539 * ((_1531 * _1531) * _1528))) * min(min((_1480 * _1480) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1337, _1504, _1182 * sqrt(fma(_1337 * _1337, _1500, _1494))), half(65504.0)), half(65504.0)), _1265, _1368) * (half4(frame.lightColor).xyz * _1337), half3(float3(65504.0)))) + min(fma((_1230 + (_1539 * ((_1890 * _1890) * _1887))) * min(min((_1839 * _1839) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1696, _1504, _1182 * sqrt(fma(_1696 * _1696, _1500, _1494))), half(65504.0)), half(65504.0)), _1265, _1368) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1614) * half(_1614)) / fast::max(_1600, 9.9999997473787516355514526367188e-05)) * half(_1633)) * half(_1633)), float3(65504.0))) * _1696), half3(float3(65504.0)))) + min(fma((_1230 + (_1539 * ((_2249 * _2249) * _2246))) * min(min((_2198 * _2198) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2055, _1504, _1182 * sqrt(fma(_2055 * _2055, _1500, _1494))), half(65504.0)), half(65504.0)), _1265, _1368) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1973) * half(_1973)) / fast::max(_1959, 9.9999997473787516355514526367188e-05)) * half(_1992)) * half(_1992)), float3(65504.0))) * _2055), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2279, half(1.0)));
    return out;
}

