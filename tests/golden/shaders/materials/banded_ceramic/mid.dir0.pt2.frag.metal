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
    float _795 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _903 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _795)), half(0.0), half(1.0));
    half3 _911 = half3((half(0.1599999964237213134765625) * _903) * _903);
    half _920 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _795)), half(0.08900000154972076416015625), half(1.0));
    half _863 = max(dot(_654, half3(_670)), half(9.9999997473787516355514526367188e-05));
    float4 _927 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_863, _920)), level(0.0));
    half3 _946 = half3(float3(1.0)) + (_911 * ((half(1.0) / half4(_927).y) - half(1.0)));
    float4 _956 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_670), _654)), level(_920 * (half(4.0) * (half(2.0) - _920))));
    float3 _1001 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1004 = dot(_1001, _1001);
    float3 _1009 = _1001 * rsqrt(fast::max(_1004, 9.9999999392252902907785028219223e-09));
    float _1013 = _1004 * float(frame.punctualLights[0].positionFalloff.w);
    float _1018 = fast::clamp(fma(-_1013, _1013, 1.0), 0.0, 1.0);
    float _1037 = fast::clamp(fma(dot(-_1009, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1171 = _920 * _920;
    half3 _1182 = normalize(half3(_670) + half3(_1009));
    half _1098 = clamp(dot(_654, half3(_1009)), half(0.0), half(1.0));
    half4 _1251 = half4(cross(_654, _1182), _1171 * clamp(dot(_654, _1182), half(0.0), half(1.0))) * half(64.0);
    half _1225 = half(4096.0) * _1171;
    half _1228 = half(6.283185482025146484375) * max(mix((half(2.0) * _1098) * _863, _1098 + _863, _1171), half(0.000244140625));
    half _1230 = _1225 / (dot(_1251, _1251) * _1228);
    float3 _1295 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1298 = dot(_1295, _1295);
    float3 _1303 = _1295 * rsqrt(fast::max(_1298, 9.9999999392252902907785028219223e-09));
    float _1307 = _1298 * float(frame.punctualLights[1].positionFalloff.w);
    float _1312 = fast::clamp(fma(-_1307, _1307, 1.0), 0.0, 1.0);
    float _1331 = fast::clamp(fma(dot(-_1303, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1476 = normalize(half3(_670) + half3(_1303));
    half _1392 = clamp(dot(_654, half3(_1303)), half(0.0), half(1.0));
    half4 _1545 = half4(cross(_654, _1476), _1171 * clamp(dot(_654, _1476), half(0.0), half(1.0))) * half(64.0);
    half _1522 = half(6.283185482025146484375) * max(mix((half(2.0) * _1392) * _863, _1392 + _863, _1171), half(0.000244140625));
    half _1524 = _1225 / (dot(_1545, _1545) * _1522);
    half3 _1553 = (fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_795))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_956).xyz * (mix(half4(_927).xxx, half4(_927).yyy, _911) * _946)) + min(((_911 * min(_1230 * (_1230 * _1228), half(65504.0))) * _946) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1018) * half(_1018)) / fast::max(_1004, 9.9999997473787516355514526367188e-05)) * half(_1037)) * half(_1037)), float3(65504.0))) * _1098), half3(float3(65504.0)))) + min(((_911 * min(_1524 * (_1524 * _1522), half(65504.0))) * _946) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1312) * half(_1312)) / fast::max(_1298, 9.9999997473787516355514526367188e-05)) * half(_1331)) * half(_1331)), float3(65504.0))) * _1392), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1553, half(1.0)));
    return out;
}

