#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float facet_perceptualRoughness;
    char _m3_pad[12];
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
    half3 _637 = normalize(half3(in.v_normal));
    float3 _643 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _841 = max(dot(_637, half3(_643)), half(9.9999997473787516355514526367188e-05));
    float4 _880 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_841, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _899 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_880).y) - half(1.0)));
    float4 _906 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_643), _637)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _951 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _954 = dot(_951, _951);
    float3 _959 = _951 * rsqrt(fast::max(_954, 9.9999999392252902907785028219223e-09));
    float _963 = _954 * float(frame.punctualLights[0].positionFalloff.w);
    float _968 = fast::clamp(fma(-_963, _963, 1.0), 0.0, 1.0);
    float _987 = fast::clamp(fma(dot(-_959, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1105 = normalize(half3(_643) + half3(_959));
    half _1050 = clamp(dot(_637, half3(_959)), half(0.0), half(1.0));
    half3 _1132 = cross(_637, _1105);
    half _1135 = clamp(dot(_637, _1105), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1152 = max(mix((half(2.0) * _1050) * _841, _1050 + _841, half(params.facet_alpha)), half(0.000244140625));
    half _1154 = half(1024.0) * half(params.facet_alpha);
    half _1159 = _1154 / (fma(_1135, _1135, dot(_1132, _1132)) * (half(6433.98193359375) * _1152));
    float3 _1221 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1224 = dot(_1221, _1221);
    float3 _1229 = _1221 * rsqrt(fast::max(_1224, 9.9999999392252902907785028219223e-09));
    float _1233 = _1224 * float(frame.punctualLights[1].positionFalloff.w);
    float _1238 = fast::clamp(fma(-_1233, _1233, 1.0), 0.0, 1.0);
    float _1257 = fast::clamp(fma(dot(-_1229, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1375 = normalize(half3(_643) + half3(_1229));
    half _1320 = clamp(dot(_637, half3(_1229)), half(0.0), half(1.0));
    half3 _1402 = cross(_637, _1375);
    half _1405 = clamp(dot(_637, _1375), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1422 = max(mix((half(2.0) * _1320) * _841, _1320 + _841, half(params.facet_alpha)), half(0.000244140625));
    half _1429 = _1154 / (fma(_1405, _1405, dot(_1402, _1402)) * (half(6433.98193359375) * _1422));
    half3 _1455 = fma(half4(_906).xyz, mix(half4(_880).xxx, half4(_880).yyy, half3(float3(params.facet_f0))) * _899, min(((half3(float3(params.facet_f0)) * min(_1159 * (_1159 * (half(6.283185482025146484375) * _1152)), half(65504.0))) * _899) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_968) * half(_968)) / fast::max(_954, 9.9999997473787516355514526367188e-05)) * half(_987)) * half(_987)), float3(65504.0))) * _1050), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1429 * (_1429 * (half(6.283185482025146484375) * _1422)), half(65504.0))) * _899) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1238) * half(_1238)) / fast::max(_1224, 9.9999997473787516355514526367188e-05)) * half(_1257)) * half(_1257)), float3(65504.0))) * _1320), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1455, half(1.0)));
    return out;
}

