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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _633 = normalize(half3(in.v_normal));
    float3 _649 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _795 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _903 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _795)), half(0.0), half(1.0));
    half3 _911 = half3((half(0.1599999964237213134765625) * _903) * _903);
    half _920 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _795)), half(0.08900000154972076416015625), half(1.0));
    half _863 = max(dot(_633, half3(_649)), half(9.9999997473787516355514526367188e-05));
    float4 _927 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_863, _920)), level(0.0));
    half3 _946 = half3(float3(1.0)) + (_911 * ((half(1.0) / half4(_927).y) - half(1.0)));
    float4 _953 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_649), _633)), level(_920 * half(4.0)));
    half3 _686 = half4(frame.lightDirection).xyz;
    half _1084 = _920 * _920;
    half3 _1095 = normalize(half3(_649) + _686);
    half _1011 = clamp(dot(_633, _686), half(0.0), half(1.0));
    half3 _1122 = cross(_633, _1095);
    half _1125 = clamp(dot(_633, _1095), half(0.0), half(1.0)) * _1084;
    half _1142 = max(mix((half(2.0) * _1011) * _863, _1011 + _863, _1084), half(0.000244140625));
    half _1144 = half(1024.0) * _1084;
    half _1149 = _1144 / (fma(_1125, _1125, dot(_1122, _1122)) * (half(6433.98193359375) * _1142));
    float3 _1197 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1200 = dot(_1197, _1197);
    float3 _1205 = _1197 * rsqrt(fast::max(_1200, 9.9999999392252902907785028219223e-09));
    float _1209 = _1200 * float(frame.punctualLights[0].positionFalloff.w);
    float _1214 = fast::clamp(fma(-_1209, _1209, 1.0), 0.0, 1.0);
    float _1233 = fast::clamp(fma(dot(-_1205, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1378 = normalize(half3(_649) + half3(_1205));
    half _1294 = clamp(dot(_633, half3(_1205)), half(0.0), half(1.0));
    half3 _1405 = cross(_633, _1378);
    half _1408 = clamp(dot(_633, _1378), half(0.0), half(1.0)) * _1084;
    half _1425 = max(mix((half(2.0) * _1294) * _863, _1294 + _863, _1084), half(0.000244140625));
    half _1432 = _1144 / (fma(_1408, _1408, dot(_1405, _1405)) * (half(6433.98193359375) * _1425));
    float3 _1480 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1483 = dot(_1480, _1480);
    float3 _1488 = _1480 * rsqrt(fast::max(_1483, 9.9999999392252902907785028219223e-09));
    float _1492 = _1483 * float(frame.punctualLights[1].positionFalloff.w);
    float _1497 = fast::clamp(fma(-_1492, _1492, 1.0), 0.0, 1.0);
    float _1516 = fast::clamp(fma(dot(-_1488, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1661 = normalize(half3(_649) + half3(_1488));
    half _1577 = clamp(dot(_633, half3(_1488)), half(0.0), half(1.0));
    half3 _1688 = cross(_633, _1661);
    half _1691 = clamp(dot(_633, _1661), half(0.0), half(1.0)) * _1084;
    half _1708 = max(mix((half(2.0) * _1577) * _863, _1577 + _863, _1084), half(0.000244140625));
    half _1715 = _1144 / (fma(_1691, _1691, dot(_1688, _1688)) * (half(6433.98193359375) * _1708));
    half3 _1727 = ((fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_795))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_953).xyz * (mix(half4(_927).xxx, half4(_927).yyy, _911) * _946)) + min(((_911 * min(_1149 * (_1149 * (half(6.283185482025146484375) * _1142)), half(65504.0))) * _946) * (half4(frame.lightColor).xyz * _1011), half3(float3(65504.0)))) + min(((_911 * min(_1432 * (_1432 * (half(6.283185482025146484375) * _1425)), half(65504.0))) * _946) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1214) * half(_1214)) / fast::max(_1200, 9.9999997473787516355514526367188e-05)) * half(_1233)) * half(_1233)), float3(65504.0))) * _1294), half3(float3(65504.0)))) + min(((_911 * min(_1715 * (_1715 * (half(6.283185482025146484375) * _1708)), half(65504.0))) * _946) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1497) * half(_1497)) / fast::max(_1483, 9.9999997473787516355514526367188e-05)) * half(_1516)) * half(_1516)), float3(65504.0))) * _1577), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1727, half(1.0)));
    return out;
}

