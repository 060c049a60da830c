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
    half3 _512 = normalize(half3(in.v_normal));
    float3 _528 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _694 = max(dot(_512, half3(_528)), half(9.9999997473787516355514526367188e-05));
    float4 _699 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_694, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _750 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1493 = half4(_699);
    half _712 = _1493.z;
    half4 _1497 = half4(_699);
    half _716 = _1497.w;
    float4 _757 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_528), _512)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _563 = half4(frame.lightDirection).xyz;
    half _814 = clamp(dot(_512, _563), half(0.0), half(1.0));
    half _818 = clamp(dot(_512, normalize(half3(_528) + _563)), half(0.0), half(1.0));
    half _860 = half(8192.0) * fma(half(-float(_814)), _694, _814 + _694);
    half _864 = half(1.0) / (half(params.facet_alpha) * _860);
    half _871 = half(2048.0) * half(params.facet_alpha);
    float3 _936 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _939 = dot(_936, _936);
    float3 _944 = _936 * rsqrt(fast::max(_939, 9.9999999392252902907785028219223e-09));
    float _948 = _939 * float(frame.punctualLights[0].positionFalloff.w);
    float _953 = fast::clamp(fma(-_948, _948, 1.0), 0.0, 1.0);
    float _972 = fast::clamp(fma(dot(-_944, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1040 = clamp(dot(_512, half3(_944)), half(0.0), half(1.0));
    half _1044 = clamp(dot(_512, normalize(half3(_528) + half3(_944))), half(0.0), half(1.0));
    half _1086 = half(8192.0) * fma(half(-float(_1040)), _694, _1040 + _694);
    half _1090 = half(1.0) / (half(params.facet_alpha) * _1086);
    float3 _1162 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1165 = dot(_1162, _1162);
    float3 _1170 = _1162 * rsqrt(fast::max(_1165, 9.9999999392252902907785028219223e-09));
    float _1174 = _1165 * float(frame.punctualLights[1].positionFalloff.w);
    float _1179 = fast::clamp(fma(-_1174, _1174, 1.0), 0.0, 1.0);
    float _1198 = fast::clamp(fma(dot(-_1170, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1266 = clamp(dot(_512, half3(_1170)), half(0.0), half(1.0));
    half _1270 = clamp(dot(_512, normalize(half3(_528) + half3(_1170))), half(0.0), half(1.0));
    half _1312 = half(8192.0) * fma(half(-float(_1266)), _694, _1266 + _694);
    half _1316 = half(1.0) / (half(params.facet_alpha) * _1312);
    half3 _1352 = ((fma(half4(_757).xyz, _750 * _712, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_750.x, max(_750.y, _750.z)))), _712, half(1.0))) + min((_750 * ((((fma(_864, _860, half(2.0)) * pow(max(fma(half(-float(_818)), _818, half(1.0)), half(0.0)), half(0.5) * (_864 * _860))) * half(0.15915493667125701904296875)) * (_814 * (_864 * _871))) * _716)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + min((_750 * ((((fma(_1090, _1086, half(2.0)) * pow(max(fma(half(-float(_1044)), _1044, half(1.0)), half(0.0)), half(0.5) * (_1090 * _1086))) * half(0.15915493667125701904296875)) * (_1040 * (_1090 * _871))) * _716)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_953) * half(_953)) / fast::max(_939, 9.9999997473787516355514526367188e-05)) * half(_972)) * half(_972)), float3(65504.0))), half3(float3(65504.0)))) + min((_750 * ((((fma(_1316, _1312, half(2.0)) * pow(max(fma(half(-float(_1270)), _1270, half(1.0)), half(0.0)), half(0.5) * (_1316 * _1312))) * half(0.15915493667125701904296875)) * (_1266 * (_1316 * _871))) * _716)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1179) * half(_1179)) / fast::max(_1165, 9.9999997473787516355514526367188e-05)) * half(_1198)) * half(_1198)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1352, half(1.0)));
    return out;
}

