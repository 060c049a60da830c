#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 fabric;
    packed_float3 sheen;
    float roughness;
    packed_float3 subsurface;
    float facet_pad44;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    half3 _625 = normalize(half3(in.v_normal));
    float3 _631 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _790 = _625.y;
    half _795 = _625.z;
    half _800 = _625.x;
    half3 _868 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _790)) + (half4(frame.sh[2]).xyz * _795)) + (half4(frame.sh[3]).xyz * _800)) + (((((half4(frame.sh[4]).xyz * (_800 * _790)) + (half4(frame.sh[5]).xyz * (_790 * _795))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _795, _795, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_800 * _795))) + (half4(frame.sh[8]).xyz * fma(_800, _800, half(-float(_790 * _790))))), half3(float3(0.0)));
    half _906 = max(dot(_625, half3(_631)), half(9.9999997473787516355514526367188e-05));
    float4 _911 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_906, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1769 = half4(_911);
    half _914 = _1769.w;
    float4 _939 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_631), _625)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _947 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half _988 = dot(_625, half3(frame.lightDirection.xyz));
    half _990 = clamp(_988, half(0.0), half(1.0));
    half _994 = clamp(dot(_625, half3(fast::normalize(_631 + frame.lightDirection.xyz))), half(0.0), half(1.0));
    half _1075 = half(2.0) + (half(1.0) / half(params.facet_alpha));
    half _1078 = half(0.5) / half(params.facet_alpha);
    float3 _1140 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1143 = dot(_1140, _1140);
    float3 _1148 = _1140 * rsqrt(fast::max(_1143, 9.9999999392252902907785028219223e-09));
    float _1152 = _1143 * float(frame.punctualLights[0].positionFalloff.w);
    float _1157 = fast::clamp(fma(-_1152, _1152, 1.0), 0.0, 1.0);
    float _1176 = fast::clamp(fma(dot(-_1148, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1224 = dot(_625, half3(_1148));
    half _1226 = clamp(_1224, half(0.0), half(1.0));
    half _1230 = clamp(dot(_625, half3(fast::normalize(_631 + _1148))), half(0.0), half(1.0));
    half3 _1266 = min(fma(half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1224 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0))), clamp(half3(float3(params.subsurface)) + half3(_1226), half3(float3(0.0)), half3(float3(1.0))), _947 * ((((_1075 * pow(max(fma(half(-float(_1230)), _1230, half(1.0)), half(0.0)), _1078)) * half(0.15915493667125701904296875)) * (_1226 / (half(4.0) * fma(half(-float(_1226)), _906, _1226 + _906)))) * _914)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1157) * half(_1157)) / fast::max(_1143, 9.9999997473787516355514526367188e-05)) * half(_1176)) * half(_1176)), float3(65504.0))), half3(float3(65504.0)));
    half3 _1340 = (fma(half3(float3(params.facet_diffuseColor)), _868, half4(_939).xyz * (_947 * half4(_911).z)) + min(fma(half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_988 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0))), clamp(half3(float3(params.subsurface)) + half3(_990), half3(float3(0.0)), half3(float3(1.0))), _947 * ((((_1075 * pow(max(fma(half(-float(_994)), _994, half(1.0)), half(0.0)), _1078)) * half(0.15915493667125701904296875)) * (_990 / (half(4.0) * fma(half(-float(_990)), _906, _990 + _906)))) * _914)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + _1266;
    float3 _1376 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1379 = dot(_1376, _1376);
    float3 _1384 = _1376 * rsqrt(fast::max(_1379, 9.9999999392252902907785028219223e-09));
    float _1388 = _1379 * float(frame.punctualLights[1].positionFalloff.w);
    float _1393 = fast::clamp(fma(-_1388, _1388, 1.0), 0.0, 1.0);
    float _1412 = fast::clamp(fma(dot(-_1384, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1460 = dot(_625, half3(_1384));
    half _1462 = clamp(_1460, half(0.0), half(1.0));
    half _1466 = clamp(dot(_625, half3(fast::normalize(_631 + _1384))), half(0.0), half(1.0));
    half3 _1502 = min(fma(half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1460 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0))), clamp(half3(float3(params.subsurface)) + half3(_1462), half3(float3(0.0)), half3(float3(1.0))), _947 * ((((_1075 * pow(max(fma(half(-float(_1466)), _1466, half(1.0)), half(0.0)), _1078)) * half(0.15915493667125701904296875)) * (_1462 / (half(4.0) * fma(half(-float(_1462)), _906, _1462 + _906)))) * _914)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1393) * half(_1393)) / fast::max(_1379, 9.9999997473787516355514526367188e-05)) * half(_1412)) * half(_1412)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1340 + _1502, half(1.0)));
    return out;
}

