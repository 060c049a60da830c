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
    half3 _638 = normalize(half3(in.v_normal));
    float3 _654 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _800 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _908 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _800)), half(0.0), half(1.0));
    half3 _916 = half3((half(0.1599999964237213134765625) * _908) * _908);
    half _925 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _800)), half(0.08900000154972076416015625), half(1.0));
    half _868 = max(dot(_638, half3(_654)), half(9.9999997473787516355514526367188e-05));
    float4 _932 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_868, _925)), level(0.0));
    half3 _951 = half3(float3(1.0)) + (_916 * ((half(1.0) / half4(_932).y) - half(1.0)));
    float4 _963 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_654), _638)), level(_925 * (half(4.0) * (half(2.0) - _925))));
    half3 _691 = half4(frame.lightDirection).xyz;
    half _1094 = _925 * _925;
    half3 _1105 = normalize(half3(_654) + _691);
    half _1021 = clamp(dot(_638, _691), half(0.0), half(1.0));
    half3 _1132 = cross(_638, _1105);
    half _1135 = clamp(dot(_638, _1105), half(0.0), half(1.0)) * _1094;
    half _1152 = max(mix((half(2.0) * _1021) * _868, _1021 + _868, _1094), half(0.000244140625));
    half _1154 = half(1024.0) * _1094;
    half _1159 = _1154 / (fma(_1135, _1135, dot(_1132, _1132)) * (half(6433.98193359375) * _1152));
    float3 _1207 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1210 = dot(_1207, _1207);
    float3 _1215 = _1207 * rsqrt(fast::max(_1210, 9.9999999392252902907785028219223e-09));
    float _1219 = _1210 * float(frame.punctualLights[0].positionFalloff.w);
    float _1224 = fast::clamp(fma(-_1219, _1219, 1.0), 0.0, 1.0);
    float _1243 = fast::clamp(fma(dot(-_1215, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1388 = normalize(half3(_654) + half3(_1215));
    half _1304 = clamp(dot(_638, half3(_1215)), half(0.0), half(1.0));
    half3 _1415 = cross(_638, _1388);
    half _1418 = clamp(dot(_638, _1388), half(0.0), half(1.0)) * _1094;
    half _1435 = max(mix((half(2.0) * _1304) * _868, _1304 + _868, _1094), half(0.000244140625));
    half _1442 = _1154 / (fma(_1418, _1418, dot(_1415, _1415)) * (half(6433.98193359375) * _1435));
    float3 _1490 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1493 = dot(_1490, _1490);
    float3 _1498 = _1490 * rsqrt(fast::max(_1493, 9.9999999392252902907785028219223e-09));
    float _1502 = _1493 * float(frame.punctualLights[1].positionFalloff.w);
    float _1507 = fast::clamp(fma(-_1502, _1502, 1.0), 0.0, 1.0);
    float _1526 = fast::clamp(fma(dot(-_1498, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1671 = normalize(half3(_654) + half3(_1498));
    half _1587 = clamp(dot(_638, half3(_1498)), half(0.0), half(1.0));
    half3 _1698 = cross(_638, _1671);
    half _1701 = clamp(dot(_638, _1671), half(0.0), half(1.0)) * _1094;
    half _1718 = max(mix((half(2.0) * _1587) * _868, _1587 + _868, _1094), half(0.000244140625));
    half _1725 = _1154 / (fma(_1701, _1701, dot(_1698, _1698)) * (half(6433.98193359375) * _1718));
    half3 _1737 = ((fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_800))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_963).xyz * (mix(half4(_932).xxx, half4(_932).yyy, _916) * _951)) + min(((_916 * min(_1159 * (_1159 * (half(6.283185482025146484375) * _1152)), half(65504.0))) * _951) * (half4(frame.lightColor).xyz * _1021), half3(float3(65504.0)))) + min(((_916 * min(_1442 * (_1442 * (half(6.283185482025146484375) * _1435)), half(65504.0))) * _951) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1224) * half(_1224)) / fast::max(_1210, 9.9999997473787516355514526367188e-05)) * half(_1243)) * half(_1243)), float3(65504.0))) * _1304), half3(float3(65504.0)))) + min(((_916 * min(_1725 * (_1725 * (half(6.283185482025146484375) * _1718)), half(65504.0))) * _951) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1507) * half(_1507)) / fast::max(_1493, 9.9999997473787516355514526367188e-05)) * half(_1526)) * half(_1526)), float3(65504.0))) * _1587), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1737, half(1.0)));
    return out;
}

