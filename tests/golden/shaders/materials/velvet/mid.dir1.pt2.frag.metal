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
    half3 _471 = normalize(half3(in.v_normal));
    float3 _487 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _650 = max(dot(_471, half3(_487)), half(9.9999997473787516355514526367188e-05));
    float4 _655 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_650, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _701 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1375 = half4(_655);
    half _668 = _1375.z;
    half4 _1379 = half4(_655);
    half _672 = _1379.w;
    float4 _708 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_487), _471)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _522 = half4(frame.lightDirection).xyz;
    half _734 = clamp(dot(_471, _522), half(0.0), half(1.0));
    half _748 = clamp(dot(_471, normalize(half3(_487) + _522)), half(0.0), half(1.0));
    half _795 = half(8192.0) * fma(half(-float(_734)), _650, _734 + _650);
    half _799 = half(1.0) / (half(params.facet_alpha) * _795);
    half _806 = half(2048.0) * half(params.facet_alpha);
    float3 _864 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _867 = dot(_864, _864);
    float3 _872 = _864 * rsqrt(fast::max(_867, 9.9999999392252902907785028219223e-09));
    float _876 = _867 * float(frame.punctualLights[0].positionFalloff.w);
    float _881 = fast::clamp(fma(-_876, _876, 1.0), 0.0, 1.0);
    float _900 = fast::clamp(fma(dot(-_872, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _937 = clamp(dot(_471, half3(_872)), half(0.0), half(1.0));
    half _951 = clamp(dot(_471, normalize(half3(_487) + half3(_872))), half(0.0), half(1.0));
    half _998 = half(8192.0) * fma(half(-float(_937)), _650, _937 + _650);
    half _1002 = half(1.0) / (half(params.facet_alpha) * _998);
    float3 _1067 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1070 = dot(_1067, _1067);
    float3 _1075 = _1067 * rsqrt(fast::max(_1070, 9.9999999392252902907785028219223e-09));
    float _1079 = _1070 * float(frame.punctualLights[1].positionFalloff.w);
    float _1084 = fast::clamp(fma(-_1079, _1079, 1.0), 0.0, 1.0);
    float _1103 = fast::clamp(fma(dot(-_1075, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1140 = clamp(dot(_471, half3(_1075)), half(0.0), half(1.0));
    half _1154 = clamp(dot(_471, normalize(half3(_487) + half3(_1075))), half(0.0), half(1.0));
    half _1201 = half(8192.0) * fma(half(-float(_1140)), _650, _1140 + _650);
    half _1205 = half(1.0) / (half(params.facet_alpha) * _1201);
    half3 _1234 = ((fma(half4(_708).xyz, _701 * _668, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_701.x, max(_701.y, _701.z)))), _668, half(1.0))) + min((_701 * ((((fma(_799, _795, half(2.0)) * pow(max(fma(half(-float(_748)), _748, half(1.0)), half(0.0)), half(0.5) * (_799 * _795))) * half(0.15915493667125701904296875)) * (_734 * (_799 * _806))) * _672)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + min((_701 * ((((fma(_1002, _998, half(2.0)) * pow(max(fma(half(-float(_951)), _951, half(1.0)), half(0.0)), half(0.5) * (_1002 * _998))) * half(0.15915493667125701904296875)) * (_937 * (_1002 * _806))) * _672)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_881) * half(_881)) / fast::max(_867, 9.9999997473787516355514526367188e-05)) * half(_900)) * half(_900)), float3(65504.0))), half3(float3(65504.0)))) + min((_701 * ((((fma(_1205, _1201, half(2.0)) * pow(max(fma(half(-float(_1154)), _1154, half(1.0)), half(0.0)), half(0.5) * (_1205 * _1201))) * half(0.15915493667125701904296875)) * (_1140 * (_1205 * _806))) * _672)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1084) * half(_1084)) / fast::max(_1070, 9.9999997473787516355514526367188e-05)) * half(_1103)) * half(_1103)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1234, half(1.0)));
    return out;
}

