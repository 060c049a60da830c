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
    half3 _765 = normalize(half3(in.v_normal));
    float3 _771 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1059 = max(dot(_765, half3(_771)), half(9.9999997473787516355514526367188e-05));
    float4 _1098 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1059, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1117 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1098).y) - half(1.0)));
    float4 _1124 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_771), _765)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1240 = fast::normalize(_771 + frame.lightDirection.xyz);
    half _1184 = clamp(dot(_765, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1280 = cross(_765, half3(_1240));
    half _1283 = clamp(dot(_765, half3(_1240)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1292 = half(params.facet_alpha) / fma(_1283, _1283, dot(_1280, _1280));
    half _1306 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1312 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1316 = sqrt(fma(_1059 * _1059, _1312, _1306));
    half _1340 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1240)), half(0.0), half(1.0));
    half _1343 = _1340 * _1340;
    half3 _1351 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1409 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1412 = dot(_1409, _1409);
    float3 _1417 = _1409 * rsqrt(fast::max(_1412, 9.9999999392252902907785028219223e-09));
    float _1421 = _1412 * float(frame.punctualLights[0].positionFalloff.w);
    float _1426 = fast::clamp(fma(-_1421, _1421, 1.0), 0.0, 1.0);
    float _1445 = fast::clamp(fma(dot(-_1417, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1564 = fast::normalize(_771 + _1417);
    half _1508 = clamp(dot(_765, half3(_1417)), half(0.0), half(1.0));
    half3 _1604 = cross(_765, half3(_1564));
    half _1607 = clamp(dot(_765, half3(_1564)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1616 = half(params.facet_alpha) / fma(_1607, _1607, dot(_1604, _1604));
    half _1664 = half(1.0) - clamp(dot(half3(_1417), half3(_1564)), half(0.0), half(1.0));
    half _1667 = _1664 * _1664;
    float3 _1733 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1736 = dot(_1733, _1733);
    float3 _1741 = _1733 * rsqrt(fast::max(_1736, 9.9999999392252902907785028219223e-09));
    float _1745 = _1736 * float(frame.punctualLights[1].positionFalloff.w);
    float _1750 = fast::clamp(fma(-_1745, _1745, 1.0), 0.0, 1.0);
    float _1769 = fast::clamp(fma(dot(-_1741, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1888 = fast::normalize(_771 + _1741);
    half _1832 = clamp(dot(_765, half3(_1741)), half(0.0), half(1.0));
    half3 _1928 = cross(_765, half3(_1888));
    half _1931 = clamp(dot(_765, half3(_1888)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1940 = half(params.facet_alpha) / fma(_1931, _1931, dot(_1928, _1928));
    half _1988 = half(1.0) - clamp(dot(half3(_1741), half3(_1888)), half(0.0), half(1.0));
    half _1991 = _1988 * _1988;
    half3 _2021 = (fma(half4(_1124).xyz, mix(half4(_1098).xxx, half4(_1098).yyy, half3(float3(params.facet_f0))) * _1117, min((((half3(float3(params.facet_f0)) + (_1351 * ((_1343 * _1343) * _1340))) * min(min((_1292 * _1292) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1184, _1316, _1059 * sqrt(fma(_1184 * _1184, _1312, _1306))), half(65504.0)), half(65504.0))) * _1117) * (half4(frame.lightColor).xyz * _1184), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1351 * ((_1667 * _1667) * _1664))) * min(min((_1616 * _1616) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1508, _1316, _1059 * sqrt(fma(_1508 * _1508, _1312, _1306))), half(65504.0)), half(65504.0))) * _1117) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1426) * half(_1426)) / fast::max(_1412, 9.9999997473787516355514526367188e-05)) * half(_1445)) * half(_1445)), float3(65504.0))) * _1508), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1351 * ((_1991 * _1991) * _1988))) * min(min((_1940 * _1940) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1832, _1316, _1059 * sqrt(fma(_1832 * _1832, _1312, _1306))), half(65504.0)), half(65504.0))) * _1117) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1750) * half(_1750)) / fast::max(_1736, 9.9999997473787516355514526367188e-05)) * half(_1769)) * half(_1769)), float3(65504.0))) * _1832), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2021, half(1.0)));
    return out;
}

