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
    half3 _787 = normalize(half3(in.v_normal));
    float3 _793 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1060 = max(dot(_787, half3(_793)), half(9.9999997473787516355514526367188e-05));
    float4 _1099 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1060, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1118 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1099).y) - half(1.0)));
    float4 _1128 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_793), _787)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1173 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1176 = dot(_1173, _1173);
    float3 _1181 = _1173 * rsqrt(fast::max(_1176, 9.9999999392252902907785028219223e-09));
    float _1185 = _1176 * float(frame.punctualLights[0].positionFalloff.w);
    float _1190 = fast::clamp(fma(-_1185, _1185, 1.0), 0.0, 1.0);
    float _1209 = fast::clamp(fma(dot(-_1181, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1328 = fast::normalize(_793 + _1181);
    half _1272 = clamp(dot(_787, half3(_1181)), half(0.0), half(1.0));
    half _1368 = half(4096.0) * half(params.facet_alpha);
    half4 _1393 = half4(cross(_787, half3(_1328)), half(params.facet_alpha) * clamp(dot(_787, half3(_1328)), half(0.0), half(1.0))) * half(64.0);
    half _1374 = _1368 / dot(_1393, _1393);
    half _1404 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1410 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1414 = sqrt(fma(_1060 * _1060, _1410, _1404));
    half _1438 = half(1.0) - clamp(dot(half3(_1181), half3(_1328)), half(0.0), half(1.0));
    half _1441 = _1438 * _1438;
    half3 _1449 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1507 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1510 = dot(_1507, _1507);
    float3 _1515 = _1507 * rsqrt(fast::max(_1510, 9.9999999392252902907785028219223e-09));
    float _1519 = _1510 * float(frame.punctualLights[1].positionFalloff.w);
    float _1524 = fast::clamp(fma(-_1519, _1519, 1.0), 0.0, 1.0);
    float _1543 = fast::clamp(fma(dot(-_1515, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1662 = fast::normalize(_793 + _1515);
    half _1606 = clamp(dot(_787, half3(_1515)), half(0.0), half(1.0));
    half4 _1727 = half4(cross(_787, half3(_1662)), half(params.facet_alpha) * clamp(dot(_787, half3(_1662)), half(0.0), half(1.0))) * half(64.0);
    half _1708 = _1368 / dot(_1727, _1727);
    half _1772 = half(1.0) - clamp(dot(half3(_1515), half3(_1662)), half(0.0), half(1.0));
    half _1775 = _1772 * _1772;
    half3 _1805 = fma(half4(_1128).xyz, mix(half4(_1099).xxx, half4(_1099).yyy, half3(float3(params.facet_f0))) * _1118, min((((half3(float3(params.facet_f0)) + (_1449 * ((_1441 * _1441) * _1438))) * min(min((_1374 * _1374) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1272, _1414, _1060 * sqrt(fma(_1272 * _1272, _1410, _1404))), half(65504.0)), half(65504.0))) * _1118) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1190) * half(_1190)) / fast::max(_1176, 9.9999997473787516355514526367188e-05)) * half(_1209)) * half(_1209)), float3(65504.0))) * _1272), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1449 * ((_1775 * _1775) * _1772))) * min(min((_1708 * _1708) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1606, _1414, _1060 * sqrt(fma(_1606 * _1606, _1410, _1404))), half(65504.0)), half(65504.0))) * _1118) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1524) * half(_1524)) / fast::max(_1510, 9.9999997473787516355514526367188e-05)) * half(_1543)) * half(_1543)), float3(65504.0))) * _1606), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1805, half(1.0)));
    return out;
}

