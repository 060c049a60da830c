#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float anisotropy;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
    packed_float3 facet_f0;
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
    half3 _585 = normalize(half3(in.v_normal));
    float3 _601 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _759 = max(dot(_585, half3(_601)), half(9.9999997473787516355514526367188e-05));
    float4 _798 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_759, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _817 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_798).y) - half(1.0)));
    float4 _824 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_601), _585)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _869 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _872 = dot(_869, _869);
    float3 _877 = _869 * rsqrt(fast::max(_872, 9.9999999392252902907785028219223e-09));
    float _881 = _872 * float(frame.punctualLights[0].positionFalloff.w);
    float _886 = fast::clamp(fma(-_881, _881, 1.0), 0.0, 1.0);
    float _905 = fast::clamp(fma(dot(-_877, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1015 = normalize(half3(_601) + half3(_877));
    half _966 = clamp(dot(_585, half3(_877)), half(0.0), half(1.0));
    half3 _1078 = cross(_585, _1015) * half(64.0);
    half _1081 = half(64.0) * half(params.facet_alpha);
    half _1082 = clamp(dot(_585, _1015), half(0.0), half(1.0)) * _1081;
    half _1058 = half(4096.0) * half(params.facet_alpha);
    half _1061 = half(6.283185482025146484375) * max(mix((half(2.0) * _966) * _759, _966 + _759, half(params.facet_alpha)), half(0.000244140625));
    half _1063 = _1058 / (fma(_1082, _1082, dot(_1078, _1078)) * _1061);
    float3 _1130 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1133 = dot(_1130, _1130);
    float3 _1138 = _1130 * rsqrt(fast::max(_1133, 9.9999999392252902907785028219223e-09));
    float _1142 = _1133 * float(frame.punctualLights[1].positionFalloff.w);
    float _1147 = fast::clamp(fma(-_1142, _1142, 1.0), 0.0, 1.0);
    float _1166 = fast::clamp(fma(dot(-_1138, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1276 = normalize(half3(_601) + half3(_1138));
    half _1227 = clamp(dot(_585, half3(_1138)), half(0.0), half(1.0));
    half3 _1339 = cross(_585, _1276) * half(64.0);
    half _1343 = clamp(dot(_585, _1276), half(0.0), half(1.0)) * _1081;
    half _1322 = half(6.283185482025146484375) * max(mix((half(2.0) * _1227) * _759, _1227 + _759, half(params.facet_alpha)), half(0.000244140625));
    half _1324 = _1058 / (fma(_1343, _1343, dot(_1339, _1339)) * _1322);
    half3 _1355 = fma(half4(_824).xyz, mix(half4(_798).xxx, half4(_798).yyy, half3(float3(params.facet_f0))) * _817, min(((half3(float3(params.facet_f0)) * min(_1063 * (_1063 * _1061), half(65504.0))) * _817) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_886) * half(_886)) / fast::max(_872, 9.9999997473787516355514526367188e-05)) * half(_905)) * half(_905)), float3(65504.0))) * _966), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1324 * (_1324 * _1322), half(65504.0))) * _817) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1147) * half(_1147)) / fast::max(_1133, 9.9999997473787516355514526367188e-05)) * half(_1166)) * half(_1166)), float3(65504.0))) * _1227), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1355, half(1.0)));
    return out;
}

