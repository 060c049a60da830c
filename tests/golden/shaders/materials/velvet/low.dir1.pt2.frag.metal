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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _506 = normalize(half3(in.v_normal));
    float3 _522 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _689 = max(dot(_506, half3(_522)), half(9.9999997473787516355514526367188e-05));
    float4 _694 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_689, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _748 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1404 = half4(_694);
    half _707 = _1404.z;
    half4 _1408 = half4(_694);
    half _714 = _1408.w;
    float4 _767 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_522), _506)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _557 = half4(frame.lightDirection).xyz;
    half _789 = clamp(dot(_506, _557), half(0.0), half(1.0));
    half _801 = clamp(dot(_506, normalize(half3(_522) + _557)), half(0.0), half(1.0));
    half _846 = half(8192.0) * fma(half(-float(_789)), _689, _789 + _689);
    half _850 = half(1.0) / (half(params.facet_alpha) * _846);
    half _857 = half(2048.0) * half(params.facet_alpha);
    float3 _915 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _918 = dot(_915, _915);
    float3 _923 = _915 * rsqrt(fast::max(_918, 9.9999999392252902907785028219223e-09));
    float _927 = _918 * float(frame.punctualLights[0].positionFalloff.w);
    float _932 = fast::clamp(fma(-_927, _927, 1.0), 0.0, 1.0);
    float _951 = fast::clamp(fma(dot(-_923, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _984 = clamp(dot(_506, half3(_923)), half(0.0), half(1.0));
    half _996 = clamp(dot(_506, normalize(half3(_522) + half3(_923))), half(0.0), half(1.0));
    half _1041 = half(8192.0) * fma(half(-float(_984)), _689, _984 + _689);
    half _1045 = half(1.0) / (half(params.facet_alpha) * _1041);
    float3 _1110 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1113 = dot(_1110, _1110);
    float3 _1118 = _1110 * rsqrt(fast::max(_1113, 9.9999999392252902907785028219223e-09));
    float _1122 = _1113 * float(frame.punctualLights[1].positionFalloff.w);
    float _1127 = fast::clamp(fma(-_1122, _1122, 1.0), 0.0, 1.0);
    float _1146 = fast::clamp(fma(dot(-_1118, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1179 = clamp(dot(_506, half3(_1118)), half(0.0), half(1.0));
    half _1191 = clamp(dot(_506, normalize(half3(_522) + half3(_1118))), half(0.0), half(1.0));
    half _1236 = half(8192.0) * fma(half(-float(_1179)), _689, _1179 + _689);
    half _1240 = half(1.0) / (half(params.facet_alpha) * _1236);
    half3 _1269 = ((fma(half4(_767).xyz, _748 * _707, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_748.x, max(_748.y, _748.z)))), _707, half(1.0))) + min((_748 * ((((fma(_850, _846, half(2.0)) * pow(max(fma(half(-float(_801)), _801, half(1.0)), half(0.0)), half(0.5) * (_850 * _846))) * half(0.15915493667125701904296875)) * (_789 * (_850 * _857))) * _714)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + min((_748 * ((((fma(_1045, _1041, half(2.0)) * pow(max(fma(half(-float(_996)), _996, half(1.0)), half(0.0)), half(0.5) * (_1045 * _1041))) * half(0.15915493667125701904296875)) * (_984 * (_1045 * _857))) * _714)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_932) * half(_932)) / fast::max(_918, 9.9999997473787516355514526367188e-05)) * half(_951)) * half(_951)), float3(65504.0))), half3(float3(65504.0)))) + min((_748 * ((((fma(_1240, _1236, half(2.0)) * pow(max(fma(half(-float(_1191)), _1191, half(1.0)), half(0.0)), half(0.5) * (_1240 * _1236))) * half(0.15915493667125701904296875)) * (_1179 * (_1240 * _857))) * _714)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1127) * half(_1127)) / fast::max(_1113, 9.9999997473787516355514526367188e-05)) * half(_1146)) * half(_1146)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1269, half(1.0)));
    return out;
}

