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
    half _769 = _625.y;
    half _774 = _625.z;
    half _779 = _625.x;
    half3 _847 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _769)) + (half4(frame.sh[2]).xyz * _774)) + (half4(frame.sh[3]).xyz * _779)) + (((((half4(frame.sh[4]).xyz * (_779 * _769)) + (half4(frame.sh[5]).xyz * (_769 * _774))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _774, _774, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_779 * _774))) + (half4(frame.sh[8]).xyz * fma(_779, _779, half(-float(_769 * _769))))), half3(float3(0.0)));
    half _885 = max(dot(_625, half3(_631)), half(9.9999997473787516355514526367188e-05));
    float4 _890 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_885, half(params.facet_perceptualRoughness))), level(0.0));
    half4 _1575 = half4(_890);
    half _893 = _1575.w;
    float4 _918 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_631), _625)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _926 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    float3 _967 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _970 = dot(_967, _967);
    float3 _975 = _967 * rsqrt(fast::max(_970, 9.9999999392252902907785028219223e-09));
    float _979 = _970 * float(frame.punctualLights[0].positionFalloff.w);
    float _984 = fast::clamp(fma(-_979, _979, 1.0), 0.0, 1.0);
    float _1003 = fast::clamp(fma(dot(-_975, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1051 = dot(_625, half3(_975));
    half _1053 = clamp(_1051, half(0.0), half(1.0));
    half _1057 = clamp(dot(_625, half3(fast::normalize(_631 + _975))), half(0.0), half(1.0));
    half _1138 = half(2.0) + (half(1.0) / half(params.facet_alpha));
    half _1141 = half(0.5) / half(params.facet_alpha);
    half3 _1093 = min(fma(half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1051 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0))), clamp(half3(float3(params.subsurface)) + half3(_1053), half3(float3(0.0)), half3(float3(1.0))), _926 * ((((_1138 * pow(max(fma(half(-float(_1057)), _1057, half(1.0)), half(0.0)), _1141)) * half(0.15915493667125701904296875)) * (_1053 / (half(4.0) * fma(half(-float(_1053)), _885, _1053 + _885)))) * _893)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_984) * half(_984)) / fast::max(_970, 9.9999997473787516355514526367188e-05)) * half(_1003)) * half(_1003)), float3(65504.0))), half3(float3(65504.0)));
    float3 _1203 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1206 = dot(_1203, _1203);
    float3 _1211 = _1203 * rsqrt(fast::max(_1206, 9.9999999392252902907785028219223e-09));
    float _1215 = _1206 * float(frame.punctualLights[1].positionFalloff.w);
    float _1220 = fast::clamp(fma(-_1215, _1215, 1.0), 0.0, 1.0);
    float _1239 = fast::clamp(fma(dot(-_1211, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1287 = dot(_625, half3(_1211));
    half _1289 = clamp(_1287, half(0.0), half(1.0));
    half _1293 = clamp(dot(_625, half3(fast::normalize(_631 + _1211))), half(0.0), half(1.0));
    half3 _1329 = min(fma(half3(float3(params.facet_diffuseColor)) * (half(0.3183098733425140380859375) * clamp((_1287 + half(0.5)) * half(0.4444444477558135986328125), half(0.0), half(1.0))), clamp(half3(float3(params.subsurface)) + half3(_1289), half3(float3(0.0)), half3(float3(1.0))), _926 * ((((_1138 * pow(max(fma(half(-float(_1293)), _1293, half(1.0)), half(0.0)), _1141)) * half(0.15915493667125701904296875)) * (_1289 / (half(4.0) * fma(half(-float(_1289)), _885, _1289 + _885)))) * _893)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1220) * half(_1220)) / fast::max(_1206, 9.9999997473787516355514526367188e-05)) * half(_1239)) * half(_1239)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half3(float3(params.facet_diffuseColor)), _847, half4(_918).xyz * (_926 * half4(_890).z)) + _1093) + _1329, half(1.0)));
    return out;
}

