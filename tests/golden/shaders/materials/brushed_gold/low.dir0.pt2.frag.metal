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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    half3 _642 = normalize(half3(in.v_normal));
    float3 _648 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _844 = max(dot(_642, half3(_648)), half(9.9999997473787516355514526367188e-05));
    float4 _886 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_844, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _905 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_886).y) - half(1.0)));
    float4 _862 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_648), _642)), level(params.facet_environmentLod));
    float3 _949 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _952 = dot(_949, _949);
    float3 _957 = _949 * rsqrt(fast::max(_952, 9.9999999392252902907785028219223e-09));
    float _961 = _952 * float(frame.punctualLights[0].positionFalloff.w);
    float _966 = fast::clamp(fma(-_961, _961, 1.0), 0.0, 1.0);
    float _985 = fast::clamp(fma(dot(-_957, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1045 = clamp(dot(_642, half3(_957)), half(0.0), half(1.0));
    half3 _1103 = normalize(half3(_648) + half3(_957));
    half4 _1172 = half4(cross(_642, _1103), half(params.facet_alpha) * clamp(dot(_642, _1103), half(0.0), half(1.0))) * half(64.0);
    half _1146 = half(4096.0) * half(params.facet_alpha);
    half _1149 = half(6.283185482025146484375) * max(mix((half(2.0) * _1045) * _844, _1045 + _844, half(params.facet_alpha)), half(0.000244140625));
    half _1151 = _1146 / (dot(_1172, _1172) * _1149);
    float3 _1230 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1233 = dot(_1230, _1230);
    float3 _1238 = _1230 * rsqrt(fast::max(_1233, 9.9999999392252902907785028219223e-09));
    float _1242 = _1233 * float(frame.punctualLights[1].positionFalloff.w);
    float _1247 = fast::clamp(fma(-_1242, _1242, 1.0), 0.0, 1.0);
    float _1266 = fast::clamp(fma(dot(-_1238, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1326 = clamp(dot(_642, half3(_1238)), half(0.0), half(1.0));
    half3 _1384 = normalize(half3(_648) + half3(_1238));
    half4 _1453 = half4(cross(_642, _1384), half(params.facet_alpha) * clamp(dot(_642, _1384), half(0.0), half(1.0))) * half(64.0);
    half _1430 = half(6.283185482025146484375) * max(mix((half(2.0) * _1326) * _844, _1326 + _844, half(params.facet_alpha)), half(0.000244140625));
    half _1432 = _1146 / (dot(_1453, _1453) * _1430);
    half3 _1475 = fma(half4(_862).xyz, mix(half4(_886).xxx, half4(_886).yyy, half3(float3(params.facet_f0))) * _905, min(((half3(float3(params.facet_f0)) * min(_1151 * (_1151 * _1149), half(65504.0))) * _905) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_966) * half(_966)) / fast::max(_952, 9.9999997473787516355514526367188e-05)) * half(_985)) * half(_985)), float3(65504.0))) * _1045), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1432 * (_1432 * _1430), half(65504.0))) * _905) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1247) * half(_1247)) / fast::max(_1233, 9.9999997473787516355514526367188e-05)) * half(_1266)) * half(_1266)), float3(65504.0))) * _1326), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1475, half(1.0)));
    return out;
}

