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
    half3 _472 = normalize(half3(in.v_normal));
    float3 _488 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _654 = max(dot(_472, half3(_488)), half(9.9999997473787516355514526367188e-05));
    float4 _659 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_654, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _705 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1379 = half4(_659);
    half _672 = _1379.z;
    half4 _1383 = half4(_659);
    half _676 = _1383.w;
    float4 _712 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_488), _472)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _523 = half4(frame.lightDirection).xyz;
    half _738 = clamp(dot(_472, _523), half(0.0), half(1.0));
    half _752 = clamp(dot(_472, normalize(half3(_488) + _523)), half(0.0), half(1.0));
    half _799 = half(8192.0) * fma(half(-float(_738)), _654, _738 + _654);
    half _803 = half(1.0) / (half(params.facet_alpha) * _799);
    half _810 = half(2048.0) * half(params.facet_alpha);
    float3 _868 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _871 = dot(_868, _868);
    float3 _876 = _868 * rsqrt(fast::max(_871, 9.9999999392252902907785028219223e-09));
    float _880 = _871 * float(frame.punctualLights[0].positionFalloff.w);
    float _885 = fast::clamp(fma(-_880, _880, 1.0), 0.0, 1.0);
    float _904 = fast::clamp(fma(dot(-_876, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _941 = clamp(dot(_472, half3(_876)), half(0.0), half(1.0));
    half _955 = clamp(dot(_472, normalize(half3(_488) + half3(_876))), half(0.0), half(1.0));
    half _1002 = half(8192.0) * fma(half(-float(_941)), _654, _941 + _654);
    half _1006 = half(1.0) / (half(params.facet_alpha) * _1002);
    float3 _1071 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1074 = dot(_1071, _1071);
    float3 _1079 = _1071 * rsqrt(fast::max(_1074, 9.9999999392252902907785028219223e-09));
    float _1083 = _1074 * float(frame.punctualLights[1].positionFalloff.w);
    float _1088 = fast::clamp(fma(-_1083, _1083, 1.0), 0.0, 1.0);
    float _1107 = fast::clamp(fma(dot(-_1079, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1144 = clamp(dot(_472, half3(_1079)), half(0.0), half(1.0));
    half _1158 = clamp(dot(_472, normalize(half3(_488) + half3(_1079))), half(0.0), half(1.0));
    half _1205 = half(8192.0) * fma(half(-float(_1144)), _654, _1144 + _654);
    half _1209 = half(1.0) / (half(params.facet_alpha) * _1205);
    half3 _1238 = ((fma(half4(_712).xyz, _705 * _672, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_705.x, max(_705.y, _705.z)))), _672, half(1.0))) + min((_705 * ((((fma(_803, _799, half(2.0)) * pow(max(fma(half(-float(_752)), _752, half(1.0)), half(0.0)), half(0.5) * (_803 * _799))) * half(0.15915493667125701904296875)) * (_738 * (_803 * _810))) * _676)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + min((_705 * ((((fma(_1006, _1002, half(2.0)) * pow(max(fma(half(-float(_955)), _955, half(1.0)), half(0.0)), half(0.5) * (_1006 * _1002))) * half(0.15915493667125701904296875)) * (_941 * (_1006 * _810))) * _676)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_885) * half(_885)) / fast::max(_871, 9.9999997473787516355514526367188e-05)) * half(_904)) * half(_904)), float3(65504.0))), half3(float3(65504.0)))) + min((_705 * ((((fma(_1209, _1205, half(2.0)) * pow(max(fma(half(-float(_1158)), _1158, half(1.0)), half(0.0)), half(0.5) * (_1209 * _1205))) * half(0.15915493667125701904296875)) * (_1144 * (_1209 * _810))) * _676)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1088) * half(_1088)) / fast::max(_1074, 9.9999997473787516355514526367188e-05)) * half(_1107)) * half(_1107)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1238, half(1.0)));
    return out;
}

