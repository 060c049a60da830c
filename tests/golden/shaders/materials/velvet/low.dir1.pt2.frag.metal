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
    half3 _503 = normalize(half3(in.v_normal));
    float3 _519 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _686 = max(dot(_503, half3(_519)), half(9.9999997473787516355514526367188e-05));
    float4 _691 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_686, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _745 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1398 = half4(_691);
    half _704 = _1398.z;
    half4 _1402 = half4(_691);
    half _711 = _1402.w;
    float4 _761 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_519), _503)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _554 = half4(frame.lightDirection).xyz;
    half _783 = clamp(dot(_503, _554), half(0.0), half(1.0));
    half _795 = clamp(dot(_503, normalize(half3(_519) + _554)), half(0.0), half(1.0));
    half _840 = half(8192.0) * fma(half(-float(_783)), _686, _783 + _686);
    half _844 = half(1.0) / (half(params.facet_alpha) * _840);
    half _851 = half(2048.0) * half(params.facet_alpha);
    float3 _909 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _912 = dot(_909, _909);
    float3 _917 = _909 * rsqrt(fast::max(_912, 9.9999999392252902907785028219223e-09));
    float _921 = _912 * float(frame.punctualLights[0].positionFalloff.w);
    float _926 = fast::clamp(fma(-_921, _921, 1.0), 0.0, 1.0);
    float _945 = fast::clamp(fma(dot(-_917, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _978 = clamp(dot(_503, half3(_917)), half(0.0), half(1.0));
    half _990 = clamp(dot(_503, normalize(half3(_519) + half3(_917))), half(0.0), half(1.0));
    half _1035 = half(8192.0) * fma(half(-float(_978)), _686, _978 + _686);
    half _1039 = half(1.0) / (half(params.facet_alpha) * _1035);
    float3 _1104 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1107 = dot(_1104, _1104);
    float3 _1112 = _1104 * rsqrt(fast::max(_1107, 9.9999999392252902907785028219223e-09));
    float _1116 = _1107 * float(frame.punctualLights[1].positionFalloff.w);
    float _1121 = fast::clamp(fma(-_1116, _1116, 1.0), 0.0, 1.0);
    float _1140 = fast::clamp(fma(dot(-_1112, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1173 = clamp(dot(_503, half3(_1112)), half(0.0), half(1.0));
    half _1185 = clamp(dot(_503, normalize(half3(_519) + half3(_1112))), half(0.0), half(1.0));
    half _1230 = half(8192.0) * fma(half(-float(_1173)), _686, _1173 + _686);
    half _1234 = half(1.0) / (half(params.facet_alpha) * _1230);
    half3 _1263 = ((fma(half4(_761).xyz, _745 * _704, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_745.x, max(_745.y, _745.z)))), _704, half(1.0))) + min((_745 * ((((fma(_844, _840, half(2.0)) * pow(max(fma(half(-float(_795)), _795, half(1.0)), half(0.0)), half(0.5) * (_844 * _840))) * half(0.15915493667125701904296875)) * (_783 * (_844 * _851))) * _711)) * half4(frame.lightColor).xyz, half3(float3(65504.0)))) + min((_745 * ((((fma(_1039, _1035, half(2.0)) * pow(max(fma(half(-float(_990)), _990, half(1.0)), half(0.0)), half(0.5) * (_1039 * _1035))) * half(0.15915493667125701904296875)) * (_978 * (_1039 * _851))) * _711)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_926) * half(_926)) / fast::max(_912, 9.9999997473787516355514526367188e-05)) * half(_945)) * half(_945)), float3(65504.0))), half3(float3(65504.0)))) + min((_745 * ((((fma(_1234, _1230, half(2.0)) * pow(max(fma(half(-float(_1185)), _1185, half(1.0)), half(0.0)), half(0.5) * (_1234 * _1230))) * half(0.15915493667125701904296875)) * (_1173 * (_1234 * _851))) * _711)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1121) * half(_1121)) / fast::max(_1107, 9.9999997473787516355514526367188e-05)) * half(_1140)) * half(_1140)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1263, half(1.0)));
    return out;
}

