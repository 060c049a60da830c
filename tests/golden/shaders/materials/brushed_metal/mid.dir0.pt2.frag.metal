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
    half3 _565 = normalize(half3(in.v_normal));
    float3 _581 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _739 = max(dot(_565, half3(_581)), half(9.9999997473787516355514526367188e-05));
    float4 _778 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_739, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _797 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_778).y) - half(1.0)));
    float4 _804 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_581), _565)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _849 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _852 = dot(_849, _849);
    float3 _857 = _849 * rsqrt(fast::max(_852, 9.9999999392252902907785028219223e-09));
    float _861 = _852 * float(frame.punctualLights[0].positionFalloff.w);
    float _866 = fast::clamp(fma(-_861, _861, 1.0), 0.0, 1.0);
    float _885 = fast::clamp(fma(dot(-_857, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _995 = normalize(half3(_581) + half3(_857));
    half _946 = clamp(dot(_565, half3(_857)), half(0.0), half(1.0));
    half3 _1022 = cross(_565, _995);
    half _1025 = clamp(dot(_565, _995), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1042 = max(mix((half(2.0) * _946) * _739, _946 + _739, half(params.facet_alpha)), half(0.000244140625));
    half _1044 = half(1024.0) * half(params.facet_alpha);
    half _1049 = _1044 / (fma(_1025, _1025, dot(_1022, _1022)) * (half(6433.98193359375) * _1042));
    float3 _1097 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1100 = dot(_1097, _1097);
    float3 _1105 = _1097 * rsqrt(fast::max(_1100, 9.9999999392252902907785028219223e-09));
    float _1109 = _1100 * float(frame.punctualLights[1].positionFalloff.w);
    float _1114 = fast::clamp(fma(-_1109, _1109, 1.0), 0.0, 1.0);
    float _1133 = fast::clamp(fma(dot(-_1105, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1243 = normalize(half3(_581) + half3(_1105));
    half _1194 = clamp(dot(_565, half3(_1105)), half(0.0), half(1.0));
    half3 _1270 = cross(_565, _1243);
    half _1273 = clamp(dot(_565, _1243), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1290 = max(mix((half(2.0) * _1194) * _739, _1194 + _739, half(params.facet_alpha)), half(0.000244140625));
    half _1297 = _1044 / (fma(_1273, _1273, dot(_1270, _1270)) * (half(6433.98193359375) * _1290));
    half3 _1309 = fma(half4(_804).xyz, mix(half4(_778).xxx, half4(_778).yyy, half3(float3(params.facet_f0))) * _797, min(((half3(float3(params.facet_f0)) * min(_1049 * (_1049 * (half(6.283185482025146484375) * _1042)), half(65504.0))) * _797) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_866) * half(_866)) / fast::max(_852, 9.9999997473787516355514526367188e-05)) * half(_885)) * half(_885)), float3(65504.0))) * _946), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1297 * (_1297 * (half(6.283185482025146484375) * _1290)), half(65504.0))) * _797) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1114) * half(_1114)) / fast::max(_1100, 9.9999997473787516355514526367188e-05)) * half(_1133)) * half(_1133)), float3(65504.0))) * _1194), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1309, half(1.0)));
    return out;
}

