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
    half3 _480 = normalize(half3(in.v_normal));
    float3 _496 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _662 = max(dot(_480, half3(_496)), half(9.9999997473787516355514526367188e-05));
    float4 _667 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_662, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _713 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1390 = half4(_667);
    half _680 = _1390.z;
    half4 _1394 = half4(_667);
    half _684 = _1394.w;
    float4 _720 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_496), _480)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _531 = half4(frame.lightDirection).xyz;
    half _746 = clamp(dot(_480, _531), half(0.0), half(1.0));
    half _760 = clamp(dot(_480, normalize(half3(_496) + _531)), half(0.0), half(1.0));
    half _818 = half(2.0) + (half(1.0) / half(params.facet_alpha));
    half _821 = half(0.5) / half(params.facet_alpha);
    float3 _877 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _880 = dot(_877, _877);
    float3 _885 = _877 * rsqrt(fast::max(_880, 9.9999999392252902907785028219223e-09));
    float _889 = _880 * float(frame.punctualLights[0].positionFalloff.w);
    float _894 = fast::clamp(fma(-_889, _889, 1.0), 0.0, 1.0);
    float _913 = fast::clamp(fma(dot(-_885, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _950 = clamp(dot(_480, half3(_885)), half(0.0), half(1.0));
    half _964 = clamp(dot(_480, normalize(half3(_496) + half3(_885))), half(0.0), half(1.0));
    float3 _1081 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1084 = dot(_1081, _1081);
    float3 _1089 = _1081 * rsqrt(fast::max(_1084, 9.9999999392252902907785028219223e-09));
    float _1093 = _1084 * float(frame.punctualLights[1].positionFalloff.w);
    float _1098 = fast::clamp(fma(-_1093, _1093, 1.0), 0.0, 1.0);
    float _1117 = fast::clamp(fma(dot(-_1089, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1154 = clamp(dot(_480, half3(_1089)), half(0.0), half(1.0));
    half _1168 = clamp(dot(_480, normalize(half3(_496) + half3(_1089))), half(0.0), half(1.0));
    half3 _1249 = ((fma(half4(_720).xyz, _713 * _680, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_713.x, max(_713.y, _713.z)))), _680, half(1.0))) + min((_713 * ((((_818 * pow(max(fma(half(-float(_760)), _760, half(1.0)), half(0.0)), _821)) * half(0.15915493667125701904296875)) * (_746 / (half(4.0) * fma(half(-float(_746)), _662, _746 + _662)))) * _684)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + min((_713 * ((((_818 * pow(max(fma(half(-float(_964)), _964, half(1.0)), half(0.0)), _821)) * half(0.15915493667125701904296875)) * (_950 / (half(4.0) * fma(half(-float(_950)), _662, _950 + _662)))) * _684)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_894) * half(_894)) / fast::max(_880, 9.9999997473787516355514526367188e-05)) * half(_913)) * half(_913)), float3(65504.0))), half3(float3(65504.0)))) + min((_713 * ((((_818 * pow(max(fma(half(-float(_1168)), _1168, half(1.0)), half(0.0)), _821)) * half(0.15915493667125701904296875)) * (_1154 / (half(4.0) * fma(half(-float(_1154)), _662, _1154 + _662)))) * _684)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1098) * half(_1098)) / fast::max(_1084, 9.9999997473787516355514526367188e-05)) * half(_1117)) * half(_1117)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1249, half(1.0)));
    return out;
}

