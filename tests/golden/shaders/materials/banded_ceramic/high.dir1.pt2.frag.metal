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
    half3 _860 = normalize(half3(in.v_normal));
    float3 _866 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1009 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _1058 = _860.y;
    half _1063 = _860.z;
    half _1068 = _860.x;
    half3 _1136 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1058)) + (half4(frame.sh[2]).xyz * _1063)) + (half4(frame.sh[3]).xyz * _1068)) + (((((half4(frame.sh[4]).xyz * (_1068 * _1058)) + (half4(frame.sh[5]).xyz * (_1058 * _1063))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1063, _1063, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1068 * _1063))) + (half4(frame.sh[8]).xyz * fma(_1068, _1068, half(-float(_1058 * _1058))))), half3(float3(0.0)));
    half3 _1159 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_1009))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1234 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _1009)), half(0.0), half(1.0));
    half3 _1242 = half3((half(0.1599999964237213134765625) * _1234) * _1234);
    half _1251 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _1009)), half(0.08900000154972076416015625), half(1.0));
    half _1194 = max(dot(_860, half3(_866)), half(9.9999997473787516355514526367188e-05));
    float4 _1258 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1194, _1251)), level(0.0));
    half3 _1277 = half3(float3(1.0)) + (_1242 * ((half(1.0) / half4(_1258).y) - half(1.0)));
    float4 _1284 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_866), _860)), level(_1251 * half(4.0)));
    half _1423 = _1251 * _1251;
    float3 _1435 = fast::normalize(_866 + frame.lightDirection.xyz);
    half _1344 = clamp(dot(_860, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1475 = half(4096.0) * _1423;
    half4 _1500 = half4(cross(_860, half3(_1435)), _1423 * clamp(dot(_860, half3(_1435)), half(0.0), half(1.0))) * half(64.0);
    half _1481 = _1475 / dot(_1500, _1500);
    half _1511 = _1423 * _1423;
    half _1517 = fma(half(-float(_1423)), _1423, half(1.0));
    half _1521 = sqrt(fma(_1194 * _1194, _1517, _1511));
    half _1545 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1435)), half(0.0), half(1.0));
    half _1548 = _1545 * _1545;
    half3 _1556 = half3(float3(1.0)) - _1242;
    half3 _1375 = _1159 * half(0.3183098733425140380859375);
    float3 _1614 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1617 = dot(_1614, _1614);
    float3 _1622 = _1614 * rsqrt(fast::max(_1617, 9.9999999392252902907785028219223e-09));
    float _1626 = _1617 * float(frame.punctualLights[0].positionFalloff.w);
    float _1631 = fast::clamp(fma(-_1626, _1626, 1.0), 0.0, 1.0);
    float _1650 = fast::clamp(fma(dot(-_1622, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1804 = fast::normalize(_866 + _1622);
    half _1713 = clamp(dot(_860, half3(_1622)), half(0.0), half(1.0));
    half4 _1869 = half4(cross(_860, half3(_1804)), _1423 * clamp(dot(_860, half3(_1804)), half(0.0), half(1.0))) * half(64.0);
    half _1850 = _1475 / dot(_1869, _1869);
    half _1914 = half(1.0) - clamp(dot(half3(_1622), half3(_1804)), half(0.0), half(1.0));
    half _1917 = _1914 * _1914;
    float3 _1983 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1986 = dot(_1983, _1983);
    float3 _1991 = _1983 * rsqrt(fast::max(_1986, 9.9999999392252902907785028219223e-09));
    float _1995 = _1986 * float(frame.punctualLights[1].positionFalloff.w);
    float _2000 = fast::clamp(fma(-_1995, _1995, 1.0), 0.0, 1.0);
    float _2019 = fast::clamp(fma(dot(-_1991, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2173 = fast::normalize(_866 + _1991);
    half _2082 = clamp(dot(_860, half3(_1991)), half(0.0), half(1.0));
    half4 _2238 = half4(cross(_860, half3(_2173)), _1423 * clamp(dot(_860, half3(_2173)), half(0.0), half(1.0))) * half(64.0);
    half _2219 = _1475 / dot(_2238, _2238);
    half _2283 = half(1.0) - clamp(dot(half3(_1991), half3(_2173)), half(0.0), half(1.0));
    half _2286 = _2283 * _2283;
    half3 _2316 = ((fma(_1159, _1136, half4(_1284).xyz * (mix(half4(_1258).xxx, half4(_1258).yyy, _1242) * _1277)) + min(fma((_1242 + (_1556 * ((_1548 * _1548) * _1545))) * min(min((_1481 * _1481) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1344, _1521, _1194 * sqrt(fma(_1344 * _1344, _1517, _1511))), half(65504.0)), half(65504.0)), _1277, _1375) * (half4(frame.lightColor).xyz * _1344), half3(float3(65504.0)))) + min(fma((_1242 + (_1556 * ((_1917 * _1917) * _1914))) * min(min((_1850 * _1850) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1713, _1521, _1194 * sqrt(fma(_1713 * _1713, _1517, _1511))), half(65504.0)), half(65504.0)), _1277, _1375) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1631) * half(_1631)) / fast::max(_1617, 9.9999997473787516355514526367188e-05)) * half(_1650)) * half(_1650)), float3(65504.0))) * _1713), half3(float3(65504.0)))) + min(fma((_1242 + (_1556 * ((_2286 * _2286) * _2283))) * min(min((_2219 * _2219) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2082, _1521, _1194 * sqrt(fma(_2082 * _2082, _1517, _1511))), half(65504.0)), half(65504.0)), _1277, _1375) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2000) * half(_2000)) / fast::max(_1986, 9.9999997473787516355514526367188e-05)) * half(_2019)) * half(_2019)), float3(65504.0))) * _2082), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2316, half(1.0)));
    return out;
}

