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
    float4 _1267 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_870), _864)), level(_1234 * half(4.0)));
    float3 _1312 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1315 = dot(_1312, _1312);
    float3 _1320 = _1312 * rsqrt(fast::max(_1315, 9.9999999392252902907785028219223e-09));
    float _1324 = _1315 * float(frame.punctualLights[0].positionFalloff.w);
    float _1329 = fast::clamp(fma(-_1324, _1324, 1.0), 0.0, 1.0);
    float _1348 = fast::clamp(fma(dot(-_1320, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1490 = _1234 * _1234;
    float3 _1502 = fast::normalize(_870 + _1320);
    half _1411 = clamp(dot(_864, half3(_1320)), half(0.0), half(1.0));
    half _1543 = half(4096.0) * _1490;
    half3 _1563 = cross(_864, half3(_1502)) * half(64.0);
    half _1566 = half(64.0) * _1490;
    half _1567 = clamp(dot(_864, half3(_1502)), half(0.0), half(1.0)) * _1566;
    half _1549 = _1543 / fma(_1567, _1567, dot(_1563, _1563));
    half _1582 = _1490 * _1490;
    half _1588 = fma(half(-float(_1490)), _1490, half(1.0));
    half _1592 = sqrt(fma(_1177 * _1177, _1588, _1582));
    half _1616 = half(1.0) - clamp(dot(half3(_1320), half3(_1502)), half(0.0), half(1.0));
    half _1619 = _1616 * _1616;
    half3 _1627 = half3(float3(1.0)) - _1225;
    half3 _1442 = _1142 * half(0.3183098733425140380859375);
    float3 _1685 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1688 = dot(_1685, _1685);
    float3 _1693 = _1685 * rsqrt(fast::max(_1688, 9.9999999392252902907785028219223e-09));
    float _1697 = _1688 * float(frame.punctualLights[1].positionFalloff.w);
    float _1702 = fast::clamp(fma(-_1697, _1697, 1.0), 0.0, 1.0);
    float _1721 = fast::clamp(fma(dot(-_1693, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1875 = fast::normalize(_870 + _1693);
    half _1784 = clamp(dot(_864, half3(_1693)), half(0.0), half(1.0));
    half3 _1936 = cross(_864, half3(_1875)) * half(64.0);
    half _1940 = clamp(dot(_864, half3(_1875)), half(0.0), half(1.0)) * _1566;
    half _1922 = _1543 / fma(_1940, _1940, dot(_1936, _1936));
    half _1989 = half(1.0) - clamp(dot(half3(_1693), half3(_1875)), half(0.0), half(1.0));
    half _1992 = _1989 * _1989;
    half3 _2022 = (fma(_1142, _1119, half4(_1267).xyz * (mix(half4(_1241).xxx, half4(_1241).yyy, _1225) * _1260)) + min(fma((_1225 + (_1627 * ((_1619 * _1619) * _1616))) * min(min((_1549 * _1549) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1411, _1592, _1177 * sqrt(fma(_1411 * _1411, _1588, _1582))), half(65504.0)), half(65504.0)), _1260, _1442) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1329) * half(_1329)) / fast::max(_1315, 9.9999997473787516355514526367188e-05)) * half(_1348)) * half(_1348)), float3(65504.0))) * _1411), half3(float3(65504.0)))) + min(fma((_1225 + (_1627 * ((_1992 * _1992) * _1989))) * min(min((_1922 * _1922) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1784, _1592, _1177 * sqrt(fma(_1784 * _1784, _1588, _1582))), half(65504.0)), half(65504.0)), _1260, _1442) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1702) * half(_1702)) / fast::max(_1688, 9.9999997473787516355514526367188e-05)) * half(_1721)) * half(_1721)), float3(65504.0))) * _1784), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2022, half(1.0)));
    return out;
}

