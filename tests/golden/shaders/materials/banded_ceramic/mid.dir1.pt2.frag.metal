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
    half3 _628 = normalize(half3(in.v_normal));
    float3 _644 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _790 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _890 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _790)), half(0.0), half(1.0));
    half3 _898 = half3((half(0.1599999964237213134765625) * _890) * _890);
    half _907 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _790)), half(0.08900000154972076416015625), half(1.0));
    half _856 = max(dot(_628, half3(_644)), half(9.9999997473787516355514526367188e-05));
    float4 _914 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_856, _907)), level(0.0));
    float4 _933 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_644), _628)), level(_907 * (half(4.0) * (half(2.0) - _907))));
    half3 _681 = half4(frame.lightDirection).xyz;
    half _1061 = _907 * _907;
    half3 _1072 = normalize(half3(_644) + _681);
    half _991 = clamp(dot(_628, _681), half(0.0), half(1.0));
    half4 _1141 = half4(cross(_628, _1072), _1061 * clamp(dot(_628, _1072), half(0.0), half(1.0))) * half(64.0);
    half _1115 = half(4096.0) * _1061;
    half _1118 = half(6.283185482025146484375) * max(mix((half(2.0) * _991) * _856, _991 + _856, _1061), half(0.000244140625));
    half _1120 = _1115 / (dot(_1141, _1141) * _1118);
    float3 _1185 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1188 = dot(_1185, _1185);
    float3 _1193 = _1185 * rsqrt(fast::max(_1188, 9.9999999392252902907785028219223e-09));
    float _1197 = _1188 * float(frame.punctualLights[0].positionFalloff.w);
    float _1202 = fast::clamp(fma(-_1197, _1197, 1.0), 0.0, 1.0);
    float _1221 = fast::clamp(fma(dot(-_1193, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1363 = normalize(half3(_644) + half3(_1193));
    half _1282 = clamp(dot(_628, half3(_1193)), half(0.0), half(1.0));
    half4 _1432 = half4(cross(_628, _1363), _1061 * clamp(dot(_628, _1363), half(0.0), half(1.0))) * half(64.0);
    half _1409 = half(6.283185482025146484375) * max(mix((half(2.0) * _1282) * _856, _1282 + _856, _1061), half(0.000244140625));
    half _1411 = _1115 / (dot(_1432, _1432) * _1409);
    float3 _1476 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1479 = dot(_1476, _1476);
    float3 _1484 = _1476 * rsqrt(fast::max(_1479, 9.9999999392252902907785028219223e-09));
    float _1488 = _1479 * float(frame.punctualLights[1].positionFalloff.w);
    float _1493 = fast::clamp(fma(-_1488, _1488, 1.0), 0.0, 1.0);
    float _1512 = fast::clamp(fma(dot(-_1484, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1654 = normalize(half3(_644) + half3(_1484));
    half _1573 = clamp(dot(_628, half3(_1484)), half(0.0), half(1.0));
    half4 _1723 = half4(cross(_628, _1654), _1061 * clamp(dot(_628, _1654), half(0.0), half(1.0))) * half(64.0);
    half _1700 = half(6.283185482025146484375) * max(mix((half(2.0) * _1573) * _856, _1573 + _856, _1061), half(0.000244140625));
    half _1702 = _1115 / (dot(_1723, _1723) * _1700);
    half3 _1731 = ((fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_790))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_933).xyz * mix(half4(_914).xxx, half4(_914).yyy, _898)) + min((_898 * min(_1120 * (_1120 * _1118), half(65504.0))) * (half4(frame.lightColor).xyz * _991), half3(float3(65504.0)))) + min((_898 * min(_1411 * (_1411 * _1409), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1202) * half(_1202)) / fast::max(_1188, 9.9999997473787516355514526367188e-05)) * half(_1221)) * half(_1221)), float3(65504.0))) * _1282), half3(float3(65504.0)))) + min((_898 * min(_1702 * (_1702 * _1700), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1493) * half(_1493)) / fast::max(_1479, 9.9999997473787516355514526367188e-05)) * half(_1512)) * half(_1512)), float3(65504.0))) * _1573), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1731, half(1.0)));
    return out;
}

