#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float facet_perceptualRoughness;
    char _m3_pad[12];
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
    half3 _771 = normalize(half3(in.v_normal));
    float3 _777 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1044 = max(dot(_771, half3(_777)), half(9.9999997473787516355514526367188e-05));
    float4 _1083 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1044, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1102 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1083).y) - half(1.0)));
    float4 _1114 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_777), _771)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1159 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1162 = dot(_1159, _1159);
    float3 _1167 = _1159 * rsqrt(fast::max(_1162, 9.9999999392252902907785028219223e-09));
    float _1171 = _1162 * float(frame.punctualLights[0].positionFalloff.w);
    float _1176 = fast::clamp(fma(-_1171, _1171, 1.0), 0.0, 1.0);
    float _1195 = fast::clamp(fma(dot(-_1167, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1314 = fast::normalize(_777 + _1167);
    half _1258 = clamp(dot(_771, half3(_1167)), half(0.0), half(1.0));
    half3 _1354 = cross(_771, half3(_1314));
    half _1357 = clamp(dot(_771, half3(_1314)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1366 = half(params.facet_alpha) / fma(_1357, _1357, dot(_1354, _1354));
    half _1380 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1386 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1390 = sqrt(fma(_1044 * _1044, _1386, _1380));
    half _1414 = half(1.0) - clamp(dot(half3(_1167), half3(_1314)), half(0.0), half(1.0));
    half _1417 = _1414 * _1414;
    half3 _1425 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1483 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1486 = dot(_1483, _1483);
    float3 _1491 = _1483 * rsqrt(fast::max(_1486, 9.9999999392252902907785028219223e-09));
    float _1495 = _1486 * float(frame.punctualLights[1].positionFalloff.w);
    float _1500 = fast::clamp(fma(-_1495, _1495, 1.0), 0.0, 1.0);
    float _1519 = fast::clamp(fma(dot(-_1491, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1638 = fast::normalize(_777 + _1491);
    half _1582 = clamp(dot(_771, half3(_1491)), half(0.0), half(1.0));
    half3 _1678 = cross(_771, half3(_1638));
    half _1681 = clamp(dot(_771, half3(_1638)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1690 = half(params.facet_alpha) / fma(_1681, _1681, dot(_1678, _1678));
    half _1738 = half(1.0) - clamp(dot(half3(_1491), half3(_1638)), half(0.0), half(1.0));
    half _1741 = _1738 * _1738;
    half3 _1771 = fma(half4(_1114).xyz, mix(half4(_1083).xxx, half4(_1083).yyy, half3(float3(params.facet_f0))) * _1102, min((((half3(float3(params.facet_f0)) + (_1425 * ((_1417 * _1417) * _1414))) * min(min((_1366 * _1366) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1258, _1390, _1044 * sqrt(fma(_1258 * _1258, _1386, _1380))), half(65504.0)), half(65504.0))) * _1102) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1176) * half(_1176)) / fast::max(_1162, 9.9999997473787516355514526367188e-05)) * half(_1195)) * half(_1195)), float3(65504.0))) * _1258), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1425 * ((_1741 * _1741) * _1738))) * min(min((_1690 * _1690) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1582, _1390, _1044 * sqrt(fma(_1582 * _1582, _1386, _1380))), half(65504.0)), half(65504.0))) * _1102) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1500) * half(_1500)) / fast::max(_1486, 9.9999997473787516355514526367188e-05)) * half(_1519)) * half(_1519)), float3(65504.0))) * _1582), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1771, half(1.0)));
    return out;
}

