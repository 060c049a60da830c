#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
    packed_float3 facet_f0;
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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _790 = normalize(half3(in.v_normal));
    float3 _806 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _964 = max(dot(_790, half3(_806)), half(9.9999997473787516355514526367188e-05));
    half3 _968 = reflect(-half3(_806), _790);
    float4 _997 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_964, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1016 = facet_environment.sample(facet_environmentSmplr, float3(_968), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1093 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1050 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_964, _1093)), level(0.0));
    half3 _1100 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2006 = half4(_1050);
    half _1063 = _2006.z;
    half _1065 = fma(half(-float(max(_1100.x, max(_1100.y, _1100.z)))), _1063, half(1.0));
    half _1109 = _1093 * _1093;
    half4 _2010 = half4(_1050);
    half _1070 = _2010.w;
    float4 _1124 = facet_environment.sample(facet_environmentSmplr, float3(_968), level(_1093 * (half(4.0) * (half(2.0) - _1093))));
    float3 _1161 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1164 = dot(_1161, _1161);
    float3 _1169 = _1161 * rsqrt(fast::max(_1164, 9.9999999392252902907785028219223e-09));
    float _1173 = _1164 * float(frame.punctualLights[0].positionFalloff.w);
    float _1178 = fast::clamp(fma(-_1173, _1173, 1.0), 0.0, 1.0);
    float _1197 = fast::clamp(fma(dot(-_1169, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1208 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1178) * half(_1178)) / fast::max(_1164, 9.9999997473787516355514526367188e-05)) * half(_1197)) * half(_1197)), float3(65504.0));
    float3 _1322 = fast::normalize(_806 + _1169);
    half _1263 = clamp(dot(_790, half3(_1169)), half(0.0), half(1.0));
    half _1267 = clamp(dot(_790, half3(_1322)), half(0.0), half(1.0));
    half _1362 = half(4096.0) * half(params.facet_alpha);
    half4 _1387 = half4(cross(_790, half3(_1322)), half(params.facet_alpha) * _1267) * half(64.0);
    half _1368 = _1362 / dot(_1387, _1387);
    half _1400 = _1263 + _964;
    half _1412 = half(1.0) - clamp(dot(half3(_1169), half3(_1322)), half(0.0), half(1.0));
    half _1415 = _1412 * _1412;
    half3 _1423 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1456 = half(8192.0) * fma(half(-float(_1263)), _964, _1400);
    half _1460 = half(1.0) / (_1109 * _1456);
    half _1467 = half(2048.0) * _1109;
    half3 _1303 = min(fma((half3(float3(params.facet_f0)) + (_1423 * ((_1415 * _1415) * _1412))) * min(min((_1368 * _1368) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1263) * _964, _1400, half(params.facet_alpha)), half(65504.0)), half(65504.0)), (half3(_1208) * _1263) * _1065, (_1100 * ((((fma(_1460, _1456, half(2.0)) * pow(max(fma(half(-float(_1267)), _1267, half(1.0)), half(0.0)), half(0.5) * (_1460 * _1456))) * half(0.15915493667125701904296875)) * (_1263 * (_1460 * _1467))) * _1070)) * half3(_1208)), half3(float3(65504.0)));
    float3 _1525 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1528 = dot(_1525, _1525);
    float3 _1533 = _1525 * rsqrt(fast::max(_1528, 9.9999999392252902907785028219223e-09));
    float _1537 = _1528 * float(frame.punctualLights[1].positionFalloff.w);
    float _1542 = fast::clamp(fma(-_1537, _1537, 1.0), 0.0, 1.0);
    float _1561 = fast::clamp(fma(dot(-_1533, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1572 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1542) * half(_1542)) / fast::max(_1528, 9.9999997473787516355514526367188e-05)) * half(_1561)) * half(_1561)), float3(65504.0));
    float3 _1686 = fast::normalize(_806 + _1533);
    half _1627 = clamp(dot(_790, half3(_1533)), half(0.0), half(1.0));
    half _1631 = clamp(dot(_790, half3(_1686)), half(0.0), half(1.0));
    half4 _1751 = half4(cross(_790, half3(_1686)), half(params.facet_alpha) * _1631) * half(64.0);
    half _1732 = _1362 / dot(_1751, _1751);
    half _1764 = _1627 + _964;
    half _1776 = half(1.0) - clamp(dot(half3(_1533), half3(_1686)), half(0.0), half(1.0));
    half _1779 = _1776 * _1776;
    half _1820 = half(8192.0) * fma(half(-float(_1627)), _964, _1764);
    half _1824 = half(1.0) / (_1109 * _1820);
    half3 _1667 = min(fma((half3(float3(params.facet_f0)) + (_1423 * ((_1779 * _1779) * _1776))) * min(min((_1732 * _1732) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1627) * _964, _1764, half(params.facet_alpha)), half(65504.0)), half(65504.0)), (half3(_1572) * _1627) * _1065, (_1100 * ((((fma(_1824, _1820, half(2.0)) * pow(max(fma(half(-float(_1631)), _1631, half(1.0)), half(0.0)), half(0.5) * (_1824 * _1820))) * half(0.15915493667125701904296875)) * (_1627 * (_1824 * _1467))) * _1070)) * half3(_1572)), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_1124).xyz, _1100 * _1063, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1016).xyz * mix(half4(_997).xxx, half4(_997).yyy, half3(float3(params.facet_f0)))) * _1065) + _1303) + _1667, half(1.0)));
    return out;
}

