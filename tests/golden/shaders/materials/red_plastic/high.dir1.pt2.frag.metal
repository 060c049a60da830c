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
    half3 _765 = normalize(half3(in.v_normal));
    float3 _771 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _926 = _765.y;
    half _931 = _765.z;
    half _936 = _765.x;
    half3 _1004 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _926)) + (half4(frame.sh[2]).xyz * _931)) + (half4(frame.sh[3]).xyz * _936)) + (((((half4(frame.sh[4]).xyz * (_936 * _926)) + (half4(frame.sh[5]).xyz * (_926 * _931))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _931, _931, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_936 * _931))) + (half4(frame.sh[8]).xyz * fma(_936, _936, half(-float(_926 * _926))))), half3(float3(0.0)));
    half _1054 = max(dot(_765, half3(_771)), half(9.9999997473787516355514526367188e-05));
    float4 _1093 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1054, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1112 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1093).y) - half(1.0)));
    float4 _1122 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_771), _765)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1238 = fast::normalize(_771 + frame.lightDirection.xyz);
    half _1182 = clamp(dot(_765, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1278 = cross(_765, half3(_1238));
    half _1281 = clamp(dot(_765, half3(_1238)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1290 = half(params.facet_alpha) / fma(_1281, _1281, dot(_1278, _1278));
    half _1304 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1310 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1314 = sqrt(fma(_1054 * _1054, _1310, _1304));
    half _1338 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1238)), half(0.0), half(1.0));
    half _1341 = _1338 * _1338;
    half3 _1349 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1213 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1399 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1402 = dot(_1399, _1399);
    float3 _1407 = _1399 * rsqrt(fast::max(_1402, 9.9999999392252902907785028219223e-09));
    float _1411 = _1402 * float(frame.punctualLights[0].positionFalloff.w);
    float _1416 = fast::clamp(fma(-_1411, _1411, 1.0), 0.0, 1.0);
    float _1435 = fast::clamp(fma(dot(-_1407, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1554 = fast::normalize(_771 + _1407);
    half _1498 = clamp(dot(_765, half3(_1407)), half(0.0), half(1.0));
    half3 _1594 = cross(_765, half3(_1554));
    half _1597 = clamp(dot(_765, half3(_1554)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1606 = half(params.facet_alpha) / fma(_1597, _1597, dot(_1594, _1594));
    half _1654 = half(1.0) - clamp(dot(half3(_1407), half3(_1554)), half(0.0), half(1.0));
    half _1657 = _1654 * _1654;
    half3 _1679 = (fma(half3(float3(params.facet_diffuseColor)), _1004, half4(_1122).xyz * (mix(half4(_1093).xxx, half4(_1093).yyy, half3(float3(params.facet_f0))) * _1112)) + min(fma((half3(float3(params.facet_f0)) + (_1349 * ((_1341 * _1341) * _1338))) * min(min((_1290 * _1290) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1182, _1314, _1054 * sqrt(fma(_1182 * _1182, _1310, _1304))), half(65504.0)), half(65504.0)), _1112, _1213) * (half4(frame.lightColor).xyz * _1182), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) + (_1349 * ((_1657 * _1657) * _1654))) * min(min((_1606 * _1606) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1498, _1314, _1054 * sqrt(fma(_1498 * _1498, _1310, _1304))), half(65504.0)), half(65504.0)), _1112, _1213) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1416) * half(_1416)) / fast::max(_1402, 9.9999997473787516355514526367188e-05)) * half(_1435)) * half(_1435)), float3(65504.0))) * _1498), half3(float3(65504.0)));
    float3 _1715 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1718 = dot(_1715, _1715);
    float3 _1723 = _1715 * rsqrt(fast::max(_1718, 9.9999999392252902907785028219223e-09));
    float _1727 = _1718 * float(frame.punctualLights[1].positionFalloff.w);
    float _1732 = fast::clamp(fma(-_1727, _1727, 1.0), 0.0, 1.0);
    float _1751 = fast::clamp(fma(dot(-_1723, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1870 = fast::normalize(_771 + _1723);
    half _1814 = clamp(dot(_765, half3(_1723)), half(0.0), half(1.0));
    half3 _1910 = cross(_765, half3(_1870));
    half _1913 = clamp(dot(_765, half3(_1870)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1922 = half(params.facet_alpha) / fma(_1913, _1913, dot(_1910, _1910));
    half _1970 = half(1.0) - clamp(dot(half3(_1723), half3(_1870)), half(0.0), half(1.0));
    half _1973 = _1970 * _1970;
    half3 _1995 = _1679 + min(fma((half3(float3(params.facet_f0)) + (_1349 * ((_1973 * _1973) * _1970))) * min(min((_1922 * _1922) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1814, _1314, _1054 * sqrt(fma(_1814 * _1814, _1310, _1304))), half(65504.0)), half(65504.0)), _1112, _1213) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1732) * half(_1732)) / fast::max(_1718, 9.9999997473787516355514526367188e-05)) * half(_1751)) * half(_1751)), float3(65504.0))) * _1814), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1995, half(1.0)));
    return out;
}

