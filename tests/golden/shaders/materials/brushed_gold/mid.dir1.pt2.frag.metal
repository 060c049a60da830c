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
    half3 _675 = normalize(half3(in.v_normal));
    float3 _681 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _900 = max(dot(_675, half3(_681)), half(9.9999997473787516355514526367188e-05));
    float4 _939 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_900, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _958 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_939).y) - half(1.0)));
    float4 _965 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_681), _675)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1081 = fast::normalize(_681 + frame.lightDirection.xyz);
    half _1025 = clamp(dot(_675, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1121 = cross(_675, half3(_1081));
    half _1124 = clamp(dot(_675, half3(_1081)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1133 = half(params.facet_alpha) / fma(_1124, _1124, dot(_1121, _1121));
    half _1161 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1081)), half(0.0), half(1.0));
    half _1164 = _1161 * _1161;
    half3 _1172 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1230 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1233 = dot(_1230, _1230);
    float3 _1238 = _1230 * rsqrt(fast::max(_1233, 9.9999999392252902907785028219223e-09));
    float _1242 = _1233 * float(frame.punctualLights[0].positionFalloff.w);
    float _1247 = fast::clamp(fma(-_1242, _1242, 1.0), 0.0, 1.0);
    float _1266 = fast::clamp(fma(dot(-_1238, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1385 = fast::normalize(_681 + _1238);
    half _1329 = clamp(dot(_675, half3(_1238)), half(0.0), half(1.0));
    half3 _1425 = cross(_675, half3(_1385));
    half _1428 = clamp(dot(_675, half3(_1385)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1437 = half(params.facet_alpha) / fma(_1428, _1428, dot(_1425, _1425));
    half _1465 = half(1.0) - clamp(dot(half3(_1238), half3(_1385)), half(0.0), half(1.0));
    half _1468 = _1465 * _1465;
    float3 _1534 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1537 = dot(_1534, _1534);
    float3 _1542 = _1534 * rsqrt(fast::max(_1537, 9.9999999392252902907785028219223e-09));
    float _1546 = _1537 * float(frame.punctualLights[1].positionFalloff.w);
    float _1551 = fast::clamp(fma(-_1546, _1546, 1.0), 0.0, 1.0);
    float _1570 = fast::clamp(fma(dot(-_1542, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1689 = fast::normalize(_681 + _1542);
    half _1633 = clamp(dot(_675, half3(_1542)), half(0.0), half(1.0));
    half3 _1729 = cross(_675, half3(_1689));
    half _1732 = clamp(dot(_675, half3(_1689)), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1741 = half(params.facet_alpha) / fma(_1732, _1732, dot(_1729, _1729));
    half _1769 = half(1.0) - clamp(dot(half3(_1542), half3(_1689)), half(0.0), half(1.0));
    half _1772 = _1769 * _1769;
    half3 _1802 = (fma(half4(_965).xyz, mix(half4(_939).xxx, half4(_939).yyy, half3(float3(params.facet_f0))) * _958, min((((half3(float3(params.facet_f0)) + (_1172 * ((_1164 * _1164) * _1161))) * min(min((_1133 * _1133) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1025) * _900, _1025 + _900, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * _958) * (half4(frame.lightColor).xyz * _1025), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1172 * ((_1468 * _1468) * _1465))) * min(min((_1437 * _1437) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1329) * _900, _1329 + _900, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * _958) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1247) * half(_1247)) / fast::max(_1233, 9.9999997473787516355514526367188e-05)) * half(_1266)) * half(_1266)), float3(65504.0))) * _1329), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1172 * ((_1772 * _1772) * _1769))) * min(min((_1741 * _1741) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1633) * _900, _1633 + _900, half(params.facet_alpha)), half(65504.0)), half(65504.0))) * _958) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1551) * half(_1551)) / fast::max(_1537, 9.9999997473787516355514526367188e-05)) * half(_1570)) * half(_1570)), float3(65504.0))) * _1633), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1802, half(1.0)));
    return out;
}

