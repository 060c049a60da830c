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
    half3 _779 = normalize(half3(in.v_normal));
    float3 _785 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _940 = _779.y;
    half _945 = _779.z;
    half _950 = _779.x;
    half3 _1018 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _940)) + (half4(frame.sh[2]).xyz * _945)) + (half4(frame.sh[3]).xyz * _950)) + (((((half4(frame.sh[4]).xyz * (_950 * _940)) + (half4(frame.sh[5]).xyz * (_940 * _945))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _945, _945, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_950 * _945))) + (half4(frame.sh[8]).xyz * fma(_950, _950, half(-float(_940 * _940))))), half3(float3(0.0)));
    half _1068 = max(dot(_779, half3(_785)), half(9.9999997473787516355514526367188e-05));
    float4 _1107 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1068, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1126 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1107).y) - half(1.0)));
    float4 _1133 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_785), _779)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1249 = fast::normalize(_785 + frame.lightDirection.xyz);
    half _1193 = clamp(dot(_779, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1289 = half(4096.0) * half(params.facet_alpha);
    half4 _1314 = half4(cross(_779, half3(_1249)), half(params.facet_alpha) * clamp(dot(_779, half3(_1249)), half(0.0), half(1.0))) * half(64.0);
    half _1295 = _1289 / dot(_1314, _1314);
    half _1325 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1331 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1335 = sqrt(fma(_1068 * _1068, _1331, _1325));
    half _1359 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1249)), half(0.0), half(1.0));
    half _1362 = _1359 * _1359;
    half3 _1370 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1224 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    float3 _1420 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1423 = dot(_1420, _1420);
    float3 _1428 = _1420 * rsqrt(fast::max(_1423, 9.9999999392252902907785028219223e-09));
    float _1432 = _1423 * float(frame.punctualLights[0].positionFalloff.w);
    float _1437 = fast::clamp(fma(-_1432, _1432, 1.0), 0.0, 1.0);
    float _1456 = fast::clamp(fma(dot(-_1428, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1575 = fast::normalize(_785 + _1428);
    half _1519 = clamp(dot(_779, half3(_1428)), half(0.0), half(1.0));
    half4 _1640 = half4(cross(_779, half3(_1575)), half(params.facet_alpha) * clamp(dot(_779, half3(_1575)), half(0.0), half(1.0))) * half(64.0);
    half _1621 = _1289 / dot(_1640, _1640);
    half _1685 = half(1.0) - clamp(dot(half3(_1428), half3(_1575)), half(0.0), half(1.0));
    half _1688 = _1685 * _1685;
    half3 _1710 = (fma(half3(float3(params.facet_diffuseColor)), _1018, half4(_1133).xyz * (mix(half4(_1107).xxx, half4(_1107).yyy, half3(float3(params.facet_f0))) * _1126)) + min(fma((half3(float3(params.facet_f0)) + (_1370 * ((_1362 * _1362) * _1359))) * min(min((_1295 * _1295) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1193, _1335, _1068 * sqrt(fma(_1193 * _1193, _1331, _1325))), half(65504.0)), half(65504.0)), _1126, _1224) * (half4(frame.lightColor).xyz * _1193), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) + (_1370 * ((_1688 * _1688) * _1685))) * min(min((_1621 * _1621) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1519, _1335, _1068 * sqrt(fma(_1519 * _1519, _1331, _1325))), half(65504.0)), half(65504.0)), _1126, _1224) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1437) * half(_1437)) / fast::max(_1423, 9.9999997473787516355514526367188e-05)) * half(_1456)) * half(_1456)), float3(65504.0))) * _1519), half3(float3(65504.0)));
    float3 _1746 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1749 = dot(_1746, _1746);
    float3 _1754 = _1746 * rsqrt(fast::max(_1749, 9.9999999392252902907785028219223e-09));
    float _1758 = _1749 * float(frame.punctualLights[1].positionFalloff.w);
    float _1763 = fast::clamp(fma(-_1758, _1758, 1.0), 0.0, 1.0);
    float _1782 = fast::clamp(fma(dot(-_1754, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1901 = fast::normalize(_785 + _1754);
    half _1845 = clamp(dot(_779, half3(_1754)), half(0.0), half(1.0));
    half4 _1966 = half4(cross(_779, half3(_1901)), half(params.facet_alpha) * clamp(dot(_779, half3(_1901)), half(0.0), half(1.0))) * half(64.0);
    half _1947 = _1289 / dot(_1966, _1966);
    half _2011 = half(1.0) - clamp(dot(half3(_1754), half3(_1901)), half(0.0), half(1.0));
    half _2014 = _2011 * _2011;
    half3 _2036 = _1710 + min(fma((half3(float3(params.facet_f0)) + (_1370 * ((_2014 * _2014) * _2011))) * min(min((_1947 * _1947) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1845, _1335, _1068 * sqrt(fma(_1845 * _1845, _1331, _1325))), half(65504.0)), half(65504.0)), _1126, _1224) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1763) * half(_1763)) / fast::max(_1749, 9.9999997473787516355514526367188e-05)) * half(_1782)) * half(_1782)), float3(65504.0))) * _1845), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2036, half(1.0)));
    return out;
}

