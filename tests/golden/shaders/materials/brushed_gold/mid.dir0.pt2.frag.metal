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
    half3 _562 = normalize(half3(in.v_normal));
    float3 _578 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _731 = max(dot(_562, half3(_578)), half(9.9999997473787516355514526367188e-05));
    float4 _770 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_731, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _789 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_770).y) - half(1.0)));
    float4 _801 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_578), _562)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _846 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _849 = dot(_846, _846);
    float3 _854 = _846 * rsqrt(fast::max(_849, 9.9999999392252902907785028219223e-09));
    float _858 = _849 * float(frame.punctualLights[0].positionFalloff.w);
    float _863 = fast::clamp(fma(-_858, _858, 1.0), 0.0, 1.0);
    float _882 = fast::clamp(fma(dot(-_854, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _992 = normalize(half3(_578) + half3(_854));
    half _943 = clamp(dot(_562, half3(_854)), half(0.0), half(1.0));
    half3 _1019 = cross(_562, _992);
    half _1022 = clamp(dot(_562, _992), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1039 = max(mix((half(2.0) * _943) * _731, _943 + _731, half(params.facet_alpha)), half(0.000244140625));
    half _1041 = half(1024.0) * half(params.facet_alpha);
    half _1046 = _1041 / (fma(_1022, _1022, dot(_1019, _1019)) * (half(6433.98193359375) * _1039));
    float3 _1094 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1097 = dot(_1094, _1094);
    float3 _1102 = _1094 * rsqrt(fast::max(_1097, 9.9999999392252902907785028219223e-09));
    float _1106 = _1097 * float(frame.punctualLights[1].positionFalloff.w);
    float _1111 = fast::clamp(fma(-_1106, _1106, 1.0), 0.0, 1.0);
    float _1130 = fast::clamp(fma(dot(-_1102, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1240 = normalize(half3(_578) + half3(_1102));
    half _1191 = clamp(dot(_562, half3(_1102)), half(0.0), half(1.0));
    half3 _1267 = cross(_562, _1240);
    half _1270 = clamp(dot(_562, _1240), half(0.0), half(1.0)) * half(params.facet_alpha);
    half _1287 = max(mix((half(2.0) * _1191) * _731, _1191 + _731, half(params.facet_alpha)), half(0.000244140625));
    half _1294 = _1041 / (fma(_1270, _1270, dot(_1267, _1267)) * (half(6433.98193359375) * _1287));
    half3 _1306 = fma(half4(_801).xyz, mix(half4(_770).xxx, half4(_770).yyy, half3(float3(params.facet_f0))) * _789, min(((half3(float3(params.facet_f0)) * min(_1046 * (_1046 * (half(6.283185482025146484375) * _1039)), half(65504.0))) * _789) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_863) * half(_863)) / fast::max(_849, 9.9999997473787516355514526367188e-05)) * half(_882)) * half(_882)), float3(65504.0))) * _943), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1294 * (_1294 * (half(6.283185482025146484375) * _1287)), half(65504.0))) * _789) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1111) * half(_1111)) / fast::max(_1097, 9.9999997473787516355514526367188e-05)) * half(_1130)) * half(_1130)), float3(65504.0))) * _1191), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1306, half(1.0)));
    return out;
}

