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
    half3 _864 = normalize(half3(in.v_normal));
    float3 _870 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1013 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _1062 = _864.y;
    half _1067 = _864.z;
    half _1072 = _864.x;
    half3 _1140 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1062)) + (half4(frame.sh[2]).xyz * _1067)) + (half4(frame.sh[3]).xyz * _1072)) + (((((half4(frame.sh[4]).xyz * (_1072 * _1062)) + (half4(frame.sh[5]).xyz * (_1062 * _1067))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1067, _1067, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1072 * _1067))) + (half4(frame.sh[8]).xyz * fma(_1072, _1072, half(-float(_1062 * _1062))))), half3(float3(0.0)));
    half3 _1163 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_1013))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1238 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _1013)), half(0.0), half(1.0));
    half3 _1246 = half3((half(0.1599999964237213134765625) * _1238) * _1238);
    half _1255 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _1013)), half(0.08900000154972076416015625), half(1.0));
    half _1198 = max(dot(_864, half3(_870)), half(9.9999997473787516355514526367188e-05));
    float4 _1262 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1198, _1255)), level(0.0));
    half3 _1281 = half3(float3(1.0)) + (_1246 * ((half(1.0) / half4(_1262).y) - half(1.0)));
    float4 _1288 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_870), _864)), level(_1255 * half(4.0)));
    half _1427 = _1255 * _1255;
    float3 _1439 = fast::normalize(_870 + frame.lightDirection.xyz);
    half _1348 = clamp(dot(_864, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1480 = half(4096.0) * _1427;
    half3 _1500 = cross(_864, half3(_1439)) * half(64.0);
    half _1503 = half(64.0) * _1427;
    half _1504 = clamp(dot(_864, half3(_1439)), half(0.0), half(1.0)) * _1503;
    half _1486 = _1480 / fma(_1504, _1504, dot(_1500, _1500));
    half _1519 = _1427 * _1427;
    half _1525 = fma(half(-float(_1427)), _1427, half(1.0));
    half _1529 = sqrt(fma(_1198 * _1198, _1525, _1519));
    half _1553 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1439)), half(0.0), half(1.0));
    half _1556 = _1553 * _1553;
    half3 _1564 = half3(float3(1.0)) - _1246;
    half3 _1379 = _1163 * half(0.3183098733425140380859375);
    float3 _1622 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1625 = dot(_1622, _1622);
    float3 _1630 = _1622 * rsqrt(fast::max(_1625, 9.9999999392252902907785028219223e-09));
    float _1634 = _1625 * float(frame.punctualLights[0].positionFalloff.w);
    float _1639 = fast::clamp(fma(-_1634, _1634, 1.0), 0.0, 1.0);
    float _1658 = fast::clamp(fma(dot(-_1630, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1812 = fast::normalize(_870 + _1630);
    half _1721 = clamp(dot(_864, half3(_1630)), half(0.0), half(1.0));
    half3 _1873 = cross(_864, half3(_1812)) * half(64.0);
    half _1877 = clamp(dot(_864, half3(_1812)), half(0.0), half(1.0)) * _1503;
    half _1859 = _1480 / fma(_1877, _1877, dot(_1873, _1873));
    half _1926 = half(1.0) - clamp(dot(half3(_1630), half3(_1812)), half(0.0), half(1.0));
    half _1929 = _1926 * _1926;
    float3 _1995 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1998 = dot(_1995, _1995);
    float3 _2003 = _1995 * rsqrt(fast::max(_1998, 9.9999999392252902907785028219223e-09));
    float _2007 = _1998 * float(frame.punctualLights[1].positionFalloff.w);
    float _2012 = fast::clamp(fma(-_2007, _2007, 1.0), 0.0, 1.0);
    float _2031 = fast::clamp(fma(dot(-_2003, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2185 = fast::normalize(_870 + _2003);
    half _2094 = clamp(dot(_864, half3(_2003)), half(0.0), half(1.0));
    half3 _2246 = cross(_864, half3(_2185)) * half(64.0);
    half _2250 = clamp(dot(_864, half3(_2185)), half(0.0), half(1.0)) * _1503;
    half _2232 = _1480 / fma(_2250, _2250, dot(_2246, _2246));
    half _2299 = half(1.0) - clamp(dot(half3(_2003), half3(_2185)), half(0.0), half(1.0));
    half _2302 = _2299 * _2299;
    half3 _2332 = ((fma(_1163, _1140, half4(_1288).xyz * (mix(half4(_1262).xxx, half4(_1262).yyy, _1246) * _1281)) + min(fma((_1246 + (_1564 * ((_1556 * _1556) * _1553))) * min(min((_1486 * _1486) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1348, _1529, _1198 * sqrt(fma(_1348 * _1348, _1525, _1519))), half(65504.0)), half(65504.0)), _1281, _1379) * (half4(frame.lightColor).xyz * _1348), half3(float3(65504.0)))) + min(fma((_1246 + (_1564 * ((_1929 * _1929) * _1926))) * min(min((_1859 * _1859) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1721, _1529, _1198 * sqrt(fma(_1721 * _1721, _1525, _1519))), half(65504.0)), half(65504.0)), _1281, _1379) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1639) * half(_1639)) / fast::max(_1625, 9.9999997473787516355514526367188e-05)) * half(_1658)) * half(_1658)), float3(65504.0))) * _1721), half3(float3(65504.0)))) + min(fma((_1246 + (_1564 * ((_2302 * _2302) * _2299))) * min(min((_2232 * _2232) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2094, _1529, _1198 * sqrt(fma(_2094 * _2094, _1525, _1519))), half(65504.0)), half(65504.0)), _1281, _1379) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2012) * half(_2012)) / fast::max(_1998, 9.9999997473787516355514526367188e-05)) * half(_2031)) * half(_2031)), float3(65504.0))) * _2094), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2332, half(1.0)));
    return out;
}

