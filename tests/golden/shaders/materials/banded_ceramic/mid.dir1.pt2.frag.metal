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
    half3 _654 = normalize(half3(in.v_normal));
    float3 _670 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _816 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _924 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _816)), half(0.0), half(1.0));
    half3 _932 = half3((half(0.1599999964237213134765625) * _924) * _924);
    half _941 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _816)), half(0.08900000154972076416015625), half(1.0));
    half _884 = max(dot(_654, half3(_670)), half(9.9999997473787516355514526367188e-05));
    float4 _948 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_884, _941)), level(0.0));
    half3 _967 = half3(float3(1.0)) + (_932 * ((half(1.0) / half4(_948).y) - half(1.0)));
    float4 _977 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_670), _654)), level(_941 * (half(4.0) * (half(2.0) - _941))));
    half3 _707 = half4(frame.lightDirection).xyz;
    half _1108 = _941 * _941;
    half3 _1119 = normalize(half3(_670) + _707);
    half _1035 = clamp(dot(_654, _707), half(0.0), half(1.0));
    half4 _1188 = half4(cross(_654, _1119), _1108 * clamp(dot(_654, _1119), half(0.0), half(1.0))) * half(64.0);
    half _1162 = half(4096.0) * _1108;
    half _1165 = half(6.283185482025146484375) * max(mix((half(2.0) * _1035) * _884, _1035 + _884, _1108), half(0.000244140625));
    half _1167 = _1162 / (dot(_1188, _1188) * _1165);
    float3 _1232 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1235 = dot(_1232, _1232);
    float3 _1240 = _1232 * rsqrt(fast::max(_1235, 9.9999999392252902907785028219223e-09));
    float _1244 = _1235 * float(frame.punctualLights[0].positionFalloff.w);
    float _1249 = fast::clamp(fma(-_1244, _1244, 1.0), 0.0, 1.0);
    float _1268 = fast::clamp(fma(dot(-_1240, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1413 = normalize(half3(_670) + half3(_1240));
    half _1329 = clamp(dot(_654, half3(_1240)), half(0.0), half(1.0));
    half4 _1482 = half4(cross(_654, _1413), _1108 * clamp(dot(_654, _1413), half(0.0), half(1.0))) * half(64.0);
    half _1459 = half(6.283185482025146484375) * max(mix((half(2.0) * _1329) * _884, _1329 + _884, _1108), half(0.000244140625));
    half _1461 = _1162 / (dot(_1482, _1482) * _1459);
    float3 _1526 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1529 = dot(_1526, _1526);
    float3 _1534 = _1526 * rsqrt(fast::max(_1529, 9.9999999392252902907785028219223e-09));
    float _1538 = _1529 * float(frame.punctualLights[1].positionFalloff.w);
    float _1543 = fast::clamp(fma(-_1538, _1538, 1.0), 0.0, 1.0);
    float _1562 = fast::clamp(fma(dot(-_1534, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1707 = normalize(half3(_670) + half3(_1534));
    half _1623 = clamp(dot(_654, half3(_1534)), half(0.0), half(1.0));
    half4 _1776 = half4(cross(_654, _1707), _1108 * clamp(dot(_654, _1707), half(0.0), half(1.0))) * half(64.0);
    half _1753 = half(6.283185482025146484375) * max(mix((half(2.0) * _1623) * _884, _1623 + _884, _1108), half(0.000244140625));
    half _1755 = _1162 / (dot(_1776, _1776) * _1753);
    half3 _1784 = ((fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_816))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_977).xyz * (mix(half4(_948).xxx, half4(_948).yyy, _932) * _967)) + min(((_932 * min(_1167 * (_1167 * _1165), half(65504.0))) * _967) * (half4(frame.lightColor).xyz * _1035), half3(float3(65504.0)))) + min(((_932 * min(_1461 * (_1461 * _1459), half(65504.0))) * _967) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1249) * half(_1249)) / fast::max(_1235, 9.9999997473787516355514526367188e-05)) * half(_1268)) * half(_1268)), float3(65504.0))) * _1329), half3(float3(65504.0)))) + min(((_932 * min(_1755 * (_1755 * _1753), half(65504.0))) * _967) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1543) * half(_1543)) / fast::max(_1529, 9.9999997473787516355514526367188e-05)) * half(_1562)) * half(_1562)), float3(65504.0))) * _1623), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1784, half(1.0)));
    return out;
}

