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
    half3 _511 = normalize(half3(in.v_normal));
    float3 _527 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _690 = max(dot(_511, half3(_527)), half(9.9999997473787516355514526367188e-05));
    float4 _695 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_690, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _746 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1489 = half4(_695);
    half _708 = _1489.z;
    half4 _1493 = half4(_695);
    half _712 = _1493.w;
    float4 _753 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_527), _511)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _562 = half4(frame.lightDirection).xyz;
    half _810 = clamp(dot(_511, _562), half(0.0), half(1.0));
    half _814 = clamp(dot(_511, normalize(half3(_527) + _562)), half(0.0), half(1.0));
    half _856 = half(8192.0) * fma(half(-float(_810)), _690, _810 + _690);
    half _860 = half(1.0) / (half(params.facet_alpha) * _856);
    half _867 = half(2048.0) * half(params.facet_alpha);
    float3 _932 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _935 = dot(_932, _932);
    float3 _940 = _932 * rsqrt(fast::max(_935, 9.9999999392252902907785028219223e-09));
    float _944 = _935 * float(frame.punctualLights[0].positionFalloff.w);
    float _949 = fast::clamp(fma(-_944, _944, 1.0), 0.0, 1.0);
    float _968 = fast::clamp(fma(dot(-_940, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1036 = clamp(dot(_511, half3(_940)), half(0.0), half(1.0));
    half _1040 = clamp(dot(_511, normalize(half3(_527) + half3(_940))), half(0.0), half(1.0));
    half _1082 = half(8192.0) * fma(half(-float(_1036)), _690, _1036 + _690);
    half _1086 = half(1.0) / (half(params.facet_alpha) * _1082);
    float3 _1158 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1161 = dot(_1158, _1158);
    float3 _1166 = _1158 * rsqrt(fast::max(_1161, 9.9999999392252902907785028219223e-09));
    float _1170 = _1161 * float(frame.punctualLights[1].positionFalloff.w);
    float _1175 = fast::clamp(fma(-_1170, _1170, 1.0), 0.0, 1.0);
    float _1194 = fast::clamp(fma(dot(-_1166, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1262 = clamp(dot(_511, half3(_1166)), half(0.0), half(1.0));
    half _1266 = clamp(dot(_511, normalize(half3(_527) + half3(_1166))), half(0.0), half(1.0));
    half _1308 = half(8192.0) * fma(half(-float(_1262)), _690, _1262 + _690);
    half _1312 = half(1.0) / (half(params.facet_alpha) * _1308);
    half3 _1348 = ((fma(half4(_753).xyz, _746 * _708, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_746.x, max(_746.y, _746.z)))), _708, half(1.0))) + min((_746 * ((((fma(_860, _856, half(2.0)) * pow(max(fma(half(-float(_814)), _814, half(1.0)), half(0.0)), half(0.5) * (_860 * _856))) * half(0.15915493667125701904296875)) * (_810 * (_860 * _867))) * _712)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + min((_746 * ((((fma(_1086, _1082, half(2.0)) * pow(max(fma(half(-float(_1040)), _1040, half(1.0)), half(0.0)), half(0.5) * (_1086 * _1082))) * half(0.15915493667125701904296875)) * (_1036 * (_1086 * _867))) * _712)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_949) * half(_949)) / fast::max(_935, 9.9999997473787516355514526367188e-05)) * half(_968)) * half(_968)), float3(65504.0))), half3(float3(65504.0)))) + min((_746 * ((((fma(_1312, _1308, half(2.0)) * pow(max(fma(half(-float(_1266)), _1266, half(1.0)), half(0.0)), half(0.5) * (_1312 * _1308))) * half(0.15915493667125701904296875)) * (_1262 * (_1312 * _867))) * _712)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1175) * half(_1175)) / fast::max(_1161, 9.9999997473787516355514526367188e-05)) * half(_1194)) * half(_1194)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1348, half(1.0)));
    return out;
}

