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
    float _992 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _1041 = _864.y;
    half _1046 = _864.z;
    half _1051 = _864.x;
    half3 _1119 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1041)) + (half4(frame.sh[2]).xyz * _1046)) + (half4(frame.sh[3]).xyz * _1051)) + (((((half4(frame.sh[4]).xyz * (_1051 * _1041)) + (half4(frame.sh[5]).xyz * (_1041 * _1046))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1046, _1046, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1051 * _1046))) + (half4(frame.sh[8]).xyz * fma(_1051, _1051, half(-float(_1041 * _1041))))), half3(float3(0.0)));
    half3 _1142 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_992))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1217 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _992)), half(0.0), half(1.0));
    half3 _1225 = half3((half(0.1599999964237213134765625) * _1217) * _1217);
    half _1234 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _992)), half(0.08900000154972076416015625), half(1.0));
    half _1177 = max(dot(_864, half3(_870)), half(9.9999997473787516355514526367188e-05));
    float4 _1241 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1177, _1234)), level(0.0));
    half3 _1260 = half3(float3(1.0)) + (_1225 * ((half(1.0) / half4(_1241).y) - half(1.0)));
    float4 _1270 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_870), _864)), level(_1234 * (half(4.0) * (half(2.0) - _1234))));
    float3 _1315 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1318 = dot(_1315, _1315);
    float3 _1323 = _1315 * rsqrt(fast::max(_1318, 9.9999999392252902907785028219223e-09));
    float _1327 = _1318 * float(frame.punctualLights[0].positionFalloff.w);
    float _1332 = fast::clamp(fma(-_1327, _1327, 1.0), 0.0, 1.0);
    float _1351 = fast::clamp(fma(dot(-_1323, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1493 = _1234 * _1234;
    float3 _1505 = fast::normalize(_870 + _1323);
    half _1414 = clamp(dot(_864, half3(_1323)), half(0.0), half(1.0));
    half _1545 = half(4096.0) * _1493;
    half4 _1570 = half4(cross(_864, half3(_1505)), _1493 * clamp(dot(_864, half3(_1505)), half(0.0), half(1.0))) * half(64.0);
    half _1551 = _1545 / dot(_1570, _1570);
    half _1581 = _1493 * _1493;
    half _1587 = fma(half(-float(_1493)), _1493, half(1.0));
    half _1591 = sqrt(fma(_1177 * _1177, _1587, _1581));
    half _1615 = half(1.0) - clamp(dot(half3(_1323), half3(_1505)), half(0.0), half(1.0));
    half _1618 = _1615 * _1615;
    half3 _1626 = half3(float3(1.0)) - _1225;
    half3 _1445 = _1142 * half(0.3183098733425140380859375);
    float3 _1684 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1687 = dot(_1684, _1684);
    float3 _1692 = _1684 * rsqrt(fast::max(_1687, 9.9999999392252902907785028219223e-09));
    float _1696 = _1687 * float(frame.punctualLights[1].positionFalloff.w);
    float _1701 = fast::clamp(fma(-_1696, _1696, 1.0), 0.0, 1.0);
    float _1720 = fast::clamp(fma(dot(-_1692, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1874 = fast::normalize(_870 + _1692);
    half _1783 = clamp(dot(_864, half3(_1692)), half(0.0), half(1.0));
    half4 _1939 = half4(cross(_864, half3(_1874)), _1493 * clamp(dot(_864, half3(_1874)), half(0.0), half(1.0))) * half(64.0);
    half _1920 = _1545 / dot(_1939, _1939);
    half _1984 = half(1.0) - clamp(dot(half3(_1692), half3(_1874)), half(0.0), half(1.0));
    half _1987 = _1984 * _1984;
    half3 _2017 = (fma(_1142, _1119, half4(_1270).xyz * (mix(half4(_1241).xxx, half4(_1241).yyy, _1225) * _1260)) + min(fma((_1225 + (_1626 * ((_1618 * _1618) * _1615))) * min(min((_1551 * _1551) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1414, _1591, _1177 * sqrt(fma(_1414 * _1414, _1587, _1581))), half(65504.0)), half(65504.0)), _1260, _1445) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1332) * half(_1332)) / fast::max(_1318, 9.9999997473787516355514526367188e-05)) * half(_1351)) * half(_1351)), float3(65504.0))) * _1414), half3(float3(65504.0)))) + min(fma((_1225 + (_1626 * ((_1987 * _1987) * _1984))) * min(min((_1920 * _1920) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1783, _1591, _1177 * sqrt(fma(_1783 * _1783, _1587, _1581))), half(65504.0)), half(65504.0)), _1260, _1445) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1701) * half(_1701)) / fast::max(_1687, 9.9999997473787516355514526367188e-05)) * half(_1720)) * half(_1720)), float3(65504.0))) * _1783), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2017, half(1.0)));
    return out;
}

