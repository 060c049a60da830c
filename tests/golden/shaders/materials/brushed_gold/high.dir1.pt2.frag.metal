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
    half3 _783 = normalize(half3(in.v_normal));
    float3 _789 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1077 = max(dot(_783, half3(_789)), half(9.9999997473787516355514526367188e-05));
    float4 _1116 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1077, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1135 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1116).y) - half(1.0)));
    float4 _1142 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_789), _783)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1258 = fast::normalize(_789 + frame.lightDirection.xyz);
    half _1202 = clamp(dot(_783, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1298 = half(4096.0) * half(params.facet_alpha);
    half4 _1323 = half4(cross(_783, half3(_1258)), half(params.facet_alpha) * clamp(dot(_783, half3(_1258)), half(0.0), half(1.0))) * half(64.0);
    half _1304 = _1298 / dot(_1323, _1323);
    half _1334 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1340 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1344 = sqrt(fma(_1077 * _1077, _1340, _1334));
    half _1368 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1258)), half(0.0), half(1.0));
    half _1371 = _1368 * _1368;
    half3 _1379 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1437 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1440 = dot(_1437, _1437);
    float3 _1445 = _1437 * rsqrt(fast::max(_1440, 9.9999999392252902907785028219223e-09));
    float _1449 = _1440 * float(frame.punctualLights[0].positionFalloff.w);
    float _1454 = fast::clamp(fma(-_1449, _1449, 1.0), 0.0, 1.0);
    float _1473 = fast::clamp(fma(dot(-_1445, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1592 = fast::normalize(_789 + _1445);
    half _1536 = clamp(dot(_783, half3(_1445)), half(0.0), half(1.0));
    half4 _1657 = half4(cross(_783, half3(_1592)), half(params.facet_alpha) * clamp(dot(_783, half3(_1592)), half(0.0), half(1.0))) * half(64.0);
    half _1638 = _1298 / dot(_1657, _1657);
    half _1702 = half(1.0) - clamp(dot(half3(_1445), half3(_1592)), half(0.0), half(1.0));
    half _1705 = _1702 * _1702;
    float3 _1771 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1774 = dot(_1771, _1771);
    float3 _1779 = _1771 * rsqrt(fast::max(_1774, 9.9999999392252902907785028219223e-09));
    float _1783 = _1774 * float(frame.punctualLights[1].positionFalloff.w);
    float _1788 = fast::clamp(fma(-_1783, _1783, 1.0), 0.0, 1.0);
    float _1807 = fast::clamp(fma(dot(-_1779, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1926 = fast::normalize(_789 + _1779);
    half _1870 = clamp(dot(_783, half3(_1779)), half(0.0), half(1.0));
    half4 _1991 = half4(cross(_783, half3(_1926)), half(params.facet_alpha) * clamp(dot(_783, half3(_1926)), half(0.0), half(1.0))) * half(64.0);
    half _1972 = _1298 / dot(_1991, _1991);
    half _2036 = half(1.0) - clamp(dot(half3(_1779), half3(_1926)), half(0.0), half(1.0));
    half _2039 = _2036 * _2036;
    half3 _2069 = (fma(half4(_1142).xyz, mix(half4(_1116).xxx, half4(_1116).yyy, half3(float3(params.facet_f0))) * _1135, min((((half3(float3(params.facet_f0)) + (_1379 * ((_1371 * _1371) * _1368))) * min(min((_1304 * _1304) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1202, _1344, _1077 * sqrt(fma(_1202 * _1202, _1340, _1334))), half(65504.0)), half(65504.0))) * _1135) * (half4(frame.lightColor).xyz * _1202), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1379 * ((_1705 * _1705) * _1702))) * min(min((_1638 * _1638) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1536, _1344, _1077 * sqrt(fma(_1536 * _1536, _1340, _1334))), half(65504.0)), half(65504.0))) * _1135) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1454) * half(_1454)) / fast::max(_1440, 9.9999997473787516355514526367188e-05)) * half(_1473)) * half(_1473)), float3(65504.0))) * _1536), half3(float3(65504.0)))) + min((((half3(float3(params.facet_f0)) + (_1379 * ((_2039 * _2039) * _2036))) * min(min((_1972 * _1972) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1870, _1344, _1077 * sqrt(fma(_1870 * _1870, _1340, _1334))), half(65504.0)), half(65504.0))) * _1135) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1788) * half(_1788)) / fast::max(_1774, 9.9999997473787516355514526367188e-05)) * half(_1807)) * half(_1807)), float3(65504.0))) * _1870), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2069, half(1.0)));
    return out;
}

