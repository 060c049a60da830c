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
    half _665 = max(dot(_503, half3(_519)), half(9.9999997473787516355514526367188e-05));
    float4 _670 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_665, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _724 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1264 = half4(_670);
    half _683 = _1264.z;
    half4 _1268 = half4(_670);
    half _690 = _1268.w;
    float4 _740 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_519), _503)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _777 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _780 = dot(_777, _777);
    float3 _785 = _777 * rsqrt(fast::max(_780, 9.9999999392252902907785028219223e-09));
    float _789 = _780 * float(frame.punctualLights[0].positionFalloff.w);
    float _794 = fast::clamp(fma(-_789, _789, 1.0), 0.0, 1.0);
    float _813 = fast::clamp(fma(dot(-_785, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _846 = clamp(dot(_503, half3(_785)), half(0.0), half(1.0));
    half _858 = clamp(dot(_503, normalize(half3(_519) + half3(_785))), half(0.0), half(1.0));
    half _903 = half(8192.0) * fma(half(-float(_846)), _665, _846 + _665);
    half _907 = half(1.0) / (half(params.facet_alpha) * _903);
    half _914 = half(2048.0) * half(params.facet_alpha);
    float3 _972 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _975 = dot(_972, _972);
    float3 _980 = _972 * rsqrt(fast::max(_975, 9.9999999392252902907785028219223e-09));
    float _984 = _975 * float(frame.punctualLights[1].positionFalloff.w);
    float _989 = fast::clamp(fma(-_984, _984, 1.0), 0.0, 1.0);
    float _1008 = fast::clamp(fma(dot(-_980, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1041 = clamp(dot(_503, half3(_980)), half(0.0), half(1.0));
    half _1053 = clamp(dot(_503, normalize(half3(_519) + half3(_980))), half(0.0), half(1.0));
    half _1098 = half(8192.0) * fma(half(-float(_1041)), _665, _1041 + _665);
    half _1102 = half(1.0) / (half(params.facet_alpha) * _1098);
    half3 _1131 = (fma(half4(_740).xyz, _724 * _683, (half3(float3(params.facet_diffuseColor)) * half3(in.v_diffuseLight)) * fma(half(-float(max(_724.x, max(_724.y, _724.z)))), _683, half(1.0))) + min((_724 * ((((fma(_907, _903, half(2.0)) * pow(max(fma(half(-float(_858)), _858, half(1.0)), half(0.0)), half(0.5) * (_907 * _903))) * half(0.15915493667125701904296875)) * (_846 * (_907 * _914))) * _690)) * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_794) * half(_794)) / fast::max(_780, 9.9999997473787516355514526367188e-05)) * half(_813)) * half(_813)), float3(65504.0))), half3(float3(65504.0)))) + min((_724 * ((((fma(_1102, _1098, half(2.0)) * pow(max(fma(half(-float(_1053)), _1053, half(1.0)), half(0.0)), half(0.5) * (_1102 * _1098))) * half(0.15915493667125701904296875)) * (_1041 * (_1102 * _914))) * _690)) * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_989) * half(_989)) / fast::max(_975, 9.9999997473787516355514526367188e-05)) * half(_1008)) * half(_1008)), float3(65504.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1131, half(1.0)));
    return out;
}

