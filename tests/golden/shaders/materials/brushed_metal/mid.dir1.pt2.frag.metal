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
    float facet_anisotropy;
    float facet_anisotropicBend;
    float2 facet_anisotropicAlpha;
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
    half3 _586 = normalize(half3(in.v_normal));
    float3 _602 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _781 = max(dot(_586, half3(_602)), half(9.9999997473787516355514526367188e-05));
    float4 _820 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_781, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _839 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_820).y) - half(1.0)));
    float4 _849 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_602), _586)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _639 = half4(frame.lightDirection).xyz;
    half3 _956 = normalize(half3(_602) + _639);
    half _907 = clamp(dot(_586, _639), half(0.0), half(1.0));
    half4 _1025 = half4(cross(_586, _956), half(params.facet_alpha) * clamp(dot(_586, _956), half(0.0), half(1.0))) * half(64.0);
    half _999 = half(4096.0) * half(params.facet_alpha);
    half _1002 = half(6.283185482025146484375) * max(mix((half(2.0) * _907) * _781, _907 + _781, half(params.facet_alpha)), half(0.000244140625));
    half _1004 = _999 / (dot(_1025, _1025) * _1002);
    float3 _1069 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1072 = dot(_1069, _1069);
    float3 _1077 = _1069 * rsqrt(fast::max(_1072, 9.9999999392252902907785028219223e-09));
    float _1081 = _1072 * float(frame.punctualLights[0].positionFalloff.w);
    float _1086 = fast::clamp(fma(-_1081, _1081, 1.0), 0.0, 1.0);
    float _1105 = fast::clamp(fma(dot(-_1077, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1215 = normalize(half3(_602) + half3(_1077));
    half _1166 = clamp(dot(_586, half3(_1077)), half(0.0), half(1.0));
    half4 _1284 = half4(cross(_586, _1215), half(params.facet_alpha) * clamp(dot(_586, _1215), half(0.0), half(1.0))) * half(64.0);
    half _1261 = half(6.283185482025146484375) * max(mix((half(2.0) * _1166) * _781, _1166 + _781, half(params.facet_alpha)), half(0.000244140625));
    half _1263 = _999 / (dot(_1284, _1284) * _1261);
    float3 _1328 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1331 = dot(_1328, _1328);
    float3 _1336 = _1328 * rsqrt(fast::max(_1331, 9.9999999392252902907785028219223e-09));
    float _1340 = _1331 * float(frame.punctualLights[1].positionFalloff.w);
    float _1345 = fast::clamp(fma(-_1340, _1340, 1.0), 0.0, 1.0);
    float _1364 = fast::clamp(fma(dot(-_1336, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1474 = normalize(half3(_602) + half3(_1336));
    half _1425 = clamp(dot(_586, half3(_1336)), half(0.0), half(1.0));
    half4 _1543 = half4(cross(_586, _1474), half(params.facet_alpha) * clamp(dot(_586, _1474), half(0.0), half(1.0))) * half(64.0);
    half _1520 = half(6.283185482025146484375) * max(mix((half(2.0) * _1425) * _781, _1425 + _781, half(params.facet_alpha)), half(0.000244140625));
    half _1522 = _999 / (dot(_1543, _1543) * _1520);
    half3 _1551 = (fma(half4(_849).xyz, mix(half4(_820).xxx, half4(_820).yyy, half3(float3(params.facet_f0))) * _839, min(((half3(float3(params.facet_f0)) * min(_1004 * (_1004 * _1002), half(65504.0))) * _839) * (half4(frame.lightColor).xyz * _907), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1263 * (_1263 * _1261), half(65504.0))) * _839) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1086) * half(_1086)) / fast::max(_1072, 9.9999997473787516355514526367188e-05)) * half(_1105)) * half(_1105)), float3(65504.0))) * _1166), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1522 * (_1522 * _1520), half(65504.0))) * _839) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1345) * half(_1345)) / fast::max(_1331, 9.9999997473787516355514526367188e-05)) * half(_1364)) * half(_1364)), float3(65504.0))) * _1425), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1551, half(1.0)));
    return out;
}

