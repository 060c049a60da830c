#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _783 = normalize(half3(in.v_normal));
    float3 _789 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _923 = _783.y;
    half _928 = _783.z;
    half _933 = _783.x;
    half3 _1001 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _923)) + (half4(frame.sh[2]).xyz * _928)) + (half4(frame.sh[3]).xyz * _933)) + (((((half4(frame.sh[4]).xyz * (_933 * _923)) + (half4(frame.sh[5]).xyz * (_923 * _928))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _928, _928, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_933 * _928))) + (half4(frame.sh[8]).xyz * fma(_933, _933, half(-float(_923 * _923))))), half3(float3(0.0)));
    half _1051 = max(dot(_783, half3(_789)), half(9.9999997473787516355514526367188e-05));
    float4 _1090 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1051, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1109 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1090).y) - half(1.0)));
    float4 _1116 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_789), _783)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1161 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1164 = dot(_1161, _1161);
    float3 _1169 = _1161 * rsqrt(fast::max(_1164, 9.9999999392252902907785028219223e-09));
    float _1173 = _1164 * float(frame.punctualLights[0].positionFalloff.w);
    float _1178 = fast::clamp(fma(-_1173, _1173, 1.0), 0.0, 1.0);
    float _1197 = fast::clamp(fma(dot(-_1169, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1316 = fast::normalize(_789 + _1169);
    half _1260 = clamp(dot(_783, half3(_1169)), half(0.0), half(1.0));
    half _1357 = half(4096.0) * half(params.facet_alpha);
    half3 _1377 = cross(_783, half3(_1316)) * half(64.0);
    half _1380 = half(64.0) * half(params.facet_alpha);
    half _1381 = clamp(dot(_783, half3(_1316)), half(0.0), half(1.0)) * _1380;
    half _1363 = _1357 / fma(_1381, _1381, dot(_1377, _1377));
    half _1396 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1402 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1406 = sqrt(fma(_1051 * _1051, _1402, _1396));
    half _1430 = half(1.0) - clamp(dot(half3(_1169), half3(_1316)), half(0.0), half(1.0));
    half _1433 = _1430 * _1430;
    half3 _1441 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1291 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1491 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1494 = dot(_1491, _1491);
    float3 _1499 = _1491 * rsqrt(fast::max(_1494, 9.9999999392252902907785028219223e-09));
    float _1503 = _1494 * float(frame.punctualLights[1].positionFalloff.w);
    float _1508 = fast::clamp(fma(-_1503, _1503, 1.0), 0.0, 1.0);
    float _1527 = fast::clamp(fma(dot(-_1499, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1646 = fast::normalize(_789 + _1499);
    half _1590 = clamp(dot(_783, half3(_1499)), half(0.0), half(1.0));
    half3 _1707 = cross(_783, half3(_1646)) * half(64.0);
    half _1711 = clamp(dot(_783, half3(_1646)), half(0.0), half(1.0)) * _1380;
    half _1693 = _1357 / fma(_1711, _1711, dot(_1707, _1707));
    half _1760 = half(1.0) - clamp(dot(half3(_1499), half3(_1646)), half(0.0), half(1.0));
    half _1763 = _1760 * _1760;
    half3 _1785 = (fma(half3(float3(params.facet_diffuseColor)), _1001, half4(_1116).xyz * (mix(half4(_1090).xxx, half4(_1090).yyy, half3(float3(params.facet_f0))) * _1109)) + min(fma((half3(float3(params.facet_f0)) + (_1441 * ((_1433 * _1433) * _1430))) * min(min((_1363 * _1363) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1260, _1406, _1051 * sqrt(fma(_1260 * _1260, _1402, _1396))), half(65504.0)), half(65504.0)), _1109, _1291) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1178) * half(_1178)) / fast::max(_1164, 9.9999997473787516355514526367188e-05)) * half(_1197)) * half(_1197)), float3(65504.0))) * _1260), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) + (_1441 * ((_1763 * _1763) * _1760))) * min(min((_1693 * _1693) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1590, _1406, _1051 * sqrt(fma(_1590 * _1590, _1402, _1396))), half(65504.0)), half(65504.0)), _1109, _1291) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1508) * half(_1508)) / fast::max(_1494, 9.9999997473787516355514526367188e-05)) * half(_1527)) * half(_1527)), float3(65504.0))) * _1590), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1785, half(1.0)));
    return out;
}

