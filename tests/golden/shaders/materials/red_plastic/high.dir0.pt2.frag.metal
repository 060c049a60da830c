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
    half3 _767 = normalize(half3(in.v_normal));
    float3 _773 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _907 = _767.y;
    half _912 = _767.z;
    half _917 = _767.x;
    half3 _985 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _907)) + (half4(frame.sh[2]).xyz * _912)) + (half4(frame.sh[3]).xyz * _917)) + (((((half4(frame.sh[4]).xyz * (_917 * _907)) + (half4(frame.sh[5]).xyz * (_907 * _912))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _912, _912, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_917 * _912))) + (half4(frame.sh[8]).xyz * fma(_917, _917, half(-float(_907 * _907))))), half3(float3(0.0)));
    half _1035 = max(dot(_767, half3(_773)), half(9.9999997473787516355514526367188e-05));
    float4 _1074 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1035, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1093 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1074).y) - half(1.0)));
    float4 _1105 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_773), _767)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1150 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1153 = dot(_1150, _1150);
    float3 _1158 = _1150 * rsqrt(fast::max(_1153, 9.9999999392252902907785028219223e-09));
    float _1162 = _1153 * float(frame.punctualLights[0].positionFalloff.w);
    float _1167 = fast::clamp(fma(-_1162, _1162, 1.0), 0.0, 1.0);
    float _1186 = fast::clamp(fma(dot(-_1158, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1305 = fast::normalize(_773 + _1158);
    half _1249 = clamp(dot(_767, half3(_1158)), half(0.0), half(1.0));
    half3 _1345 = cross(_767, half3(_1305));
    half _1348 = clamp(dot(_767, half3(_1305)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1357 = half(params.facet_alpha) / fma(_1348, _1348, dot(_1345, _1345));
    half _1371 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1377 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1381 = sqrt(fma(_1035 * _1035, _1377, _1371));
    half _1405 = half(1.0) - clamp(dot(half3(_1158), half3(_1305)), half(0.0), half(1.0));
    half _1408 = _1405 * _1405;
    half3 _1416 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1280 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1466 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1469 = dot(_1466, _1466);
    float3 _1474 = _1466 * rsqrt(fast::max(_1469, 9.9999999392252902907785028219223e-09));
    float _1478 = _1469 * float(frame.punctualLights[1].positionFalloff.w);
    float _1483 = fast::clamp(fma(-_1478, _1478, 1.0), 0.0, 1.0);
    float _1502 = fast::clamp(fma(dot(-_1474, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1621 = fast::normalize(_773 + _1474);
    half _1565 = clamp(dot(_767, half3(_1474)), half(0.0), half(1.0));
    half3 _1661 = cross(_767, half3(_1621));
    half _1664 = clamp(dot(_767, half3(_1621)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1673 = half(params.facet_alpha) / fma(_1664, _1664, dot(_1661, _1661));
    half _1721 = half(1.0) - clamp(dot(half3(_1474), half3(_1621)), half(0.0), half(1.0));
    half _1724 = _1721 * _1721;
    half3 _1746 = (fma(half3(float3(params.facet_diffuseColor)), _985, half4(_1105).xyz * (mix(half4(_1074).xxx, half4(_1074).yyy, half3(float3(params.facet_f0))) * _1093)) + min(fma((half3(float3(params.facet_f0)) + (_1416 * ((_1408 * _1408) * _1405))) * min(min((_1357 * _1357) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1249, _1381, _1035 * sqrt(fma(_1249 * _1249, _1377, _1371))), half(65504.0)), half(65504.0)), _1093, _1280) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1167) * half(_1167)) / fast::max(_1153, 9.9999997473787516355514526367188e-05)) * half(_1186)) * half(_1186)), float3(65504.0))) * _1249), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) + (_1416 * ((_1724 * _1724) * _1721))) * min(min((_1673 * _1673) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1565, _1381, _1035 * sqrt(fma(_1565 * _1565, _1377, _1371))), half(65504.0)), half(65504.0)), _1093, _1280) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1483) * half(_1483)) / fast::max(_1469, 9.9999997473787516355514526367188e-05)) * half(_1502)) * half(_1502)), float3(65504.0))) * _1565), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1746, half(1.0)));
    return out;
}

