#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    float facet_alpha;
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
    half3 _678 = normalize(half3(in.v_normal));
    float3 _684 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _841 = _678.y;
    half _846 = _678.z;
    half _851 = _678.x;
    half3 _919 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _841)) + (half4(frame.sh[2]).xyz * _846)) + (half4(frame.sh[3]).xyz * _851)) + (((((half4(frame.sh[4]).xyz * (_851 * _841)) + (half4(frame.sh[5]).xyz * (_841 * _846))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _846, _846, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_851 * _846))) + (half4(frame.sh[8]).xyz * fma(_851, _851, half(-float(_841 * _841))))), half3(float3(0.0)));
    half _960 = max(dot(_678, half3(_684)), half(9.9999997473787516355514526367188e-05));
    float4 _965 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_960, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1019 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1843 = half4(_965);
    half _978 = _1843.z;
    half _980 = fma(half(-float(max(_1019.x, max(_1019.y, _1019.z)))), _978, half(1.0));
    half4 _1847 = half4(_965);
    half _985 = _1847.w;
    float4 _1040 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_684), _678)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1063 = dot(_678, half3(frame.lightDirection.xyz));
    half _1065 = clamp(_1063, half(0.0), half(1.0));
    half _1077 = clamp(dot(_678, half3(fast::normalize(_684 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half _1148 = half(8192.0) * fma(half(-float(_1065)), _960, _1065 + _960);
    half _1152 = half(1.0) / (half(params.facet_alpha) * _1148);
    half _1159 = half(2048.0) * half(params.facet_alpha);
    float3 _1223 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1226 = dot(_1223, _1223);
    float3 _1231 = _1223 * rsqrt(fast::max(_1226, 9.9999999392252902907785028219223e-09));
    float _1235 = _1226 * float(frame.punctualLights[0].positionFalloff.w);
    float _1240 = fast::clamp(fma(-_1235, _1235, 1.0), 0.0, 1.0);
    float _1259 = fast::clamp(fma(dot(-_1231, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1293 = dot(_678, half3(_1231));
    half _1295 = clamp(_1293, half(0.0), half(1.0));
    half _1307 = clamp(dot(_678, half3(fast::normalize(_684 + _1231))), half(0.0), half(1.0));
    half _1378 = half(8192.0) * fma(half(-float(_1295)), _960, _1295 + _960);
    half _1382 = half(1.0) / (half(params.facet_alpha) * _1378);
    half3 _1340 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1293 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1295), half3(float3(0.0)), half3(float3(1.0)))) * _980) + (_1019 * ((((fma(_1382, _1378, half(2.0)) * pow(max(fma(half(-float(_1307)), _1307, half(1.0)), half(0.0)), half(0.5) * (_1382 * _1378))) * half(0.15915493667125701904296875)) * (_1295 * (_1382 * _1159))) * _985))) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1240) * half(_1240)) / fast::max(_1226, 9.9999997473787516355514526367188e-05)) * half(_1259)) * half(_1259)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1417 = (fma(half4(_1040).xyz, _1019 * _978, (half3(float3(params.facet_diffuseColor)) * _919) * _980) + min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1063 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1065), half3(float3(0.0)), half3(float3(1.0)))) * _980) + (_1019 * ((((fma(_1152, _1148, half(2.0)) * pow(max(fma(half(-float(_1077)), _1077, half(1.0)), half(0.0)), half(0.5) * (_1152 * _1148))) * half(0.15915493667125701904296875)) * (_1065 * (_1152 * _1159))) * _985))) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1340;
    float3 _1453 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1456 = dot(_1453, _1453);
    float3 _1461 = _1453 * rsqrt(fast::max(_1456, 9.9999999392252902907785028219223e-09));
    float _1465 = _1456 * float(frame.punctualLights[1].positionFalloff.w);
    float _1470 = fast::clamp(fma(-_1465, _1465, 1.0), 0.0, 1.0);
    float _1489 = fast::clamp(fma(dot(-_1461, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1523 = dot(_678, half3(_1461));
    half _1525 = clamp(_1523, half(0.0), half(1.0));
    half _1537 = clamp(dot(_678, half3(fast::normalize(_684 + _1461))), half(0.0), half(1.0));
    half _1608 = half(8192.0) * fma(half(-float(_1525)), _960, _1525 + _960);
    half _1612 = half(1.0) / (half(params.facet_alpha) * _1608);
    half3 _1570 = min(((((half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1523 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0)))) * clamp(half3(float3(params.subsurface)) + half3(_1525), half3(float3(0.0)), half3(float3(1.0)))) * _980) + (_1019 * ((((fma(_1612, _1608, half(2.0)) * pow(max(fma(half(-float(_1537)), _1537, half(1.0)), half(0.0)), half(0.5) * (_1612 * _1608))) * half(0.15915493667125701904296875)) * (_1525 * (_1612 * _1159))) * _985))) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1470) * half(_1470)) / fast::max(_1456, 9.9999997473787516355514526367188e-05)) * half(_1489)) * half(_1489)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1417 + _1570, half(1.0)));
    return out;
}

