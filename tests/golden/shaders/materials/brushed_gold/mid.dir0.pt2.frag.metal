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
    half3 _577 = normalize(half3(in.v_normal));
    float3 _593 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _746 = max(dot(_577, half3(_593)), half(9.9999997473787516355514526367188e-05));
    float4 _785 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_746, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _804 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_785).y) - half(1.0)));
    float4 _811 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_593), _577)), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _856 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _859 = dot(_856, _856);
    float3 _864 = _856 * rsqrt(fast::max(_859, 9.9999999392252902907785028219223e-09));
    float _868 = _859 * float(frame.punctualLights[0].positionFalloff.w);
    float _873 = fast::clamp(fma(-_868, _868, 1.0), 0.0, 1.0);
    float _892 = fast::clamp(fma(dot(-_864, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1002 = normalize(half3(_593) + half3(_864));
    half _953 = clamp(dot(_577, half3(_864)), half(0.0), half(1.0));
    half3 _1065 = cross(_577, _1002) * half(64.0);
    half _1068 = half(64.0) * half(params.facet_alpha);
    half _1069 = clamp(dot(_577, _1002), half(0.0), half(1.0)) * _1068;
    half _1045 = half(4096.0) * half(params.facet_alpha);
    half _1048 = half(6.283185482025146484375) * max(mix((half(2.0) * _953) * _746, _953 + _746, half(params.facet_alpha)), half(0.000244140625));
    half _1050 = _1045 / (fma(_1069, _1069, dot(_1065, _1065)) * _1048);
    float3 _1117 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1120 = dot(_1117, _1117);
    float3 _1125 = _1117 * rsqrt(fast::max(_1120, 9.9999999392252902907785028219223e-09));
    float _1129 = _1120 * float(frame.punctualLights[1].positionFalloff.w);
    float _1134 = fast::clamp(fma(-_1129, _1129, 1.0), 0.0, 1.0);
    float _1153 = fast::clamp(fma(dot(-_1125, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1263 = normalize(half3(_593) + half3(_1125));
    half _1214 = clamp(dot(_577, half3(_1125)), half(0.0), half(1.0));
    half3 _1326 = cross(_577, _1263) * half(64.0);
    half _1330 = clamp(dot(_577, _1263), half(0.0), half(1.0)) * _1068;
    half _1309 = half(6.283185482025146484375) * max(mix((half(2.0) * _1214) * _746, _1214 + _746, half(params.facet_alpha)), half(0.000244140625));
    half _1311 = _1045 / (fma(_1330, _1330, dot(_1326, _1326)) * _1309);
    half3 _1342 = fma(half4(_811).xyz, mix(half4(_785).xxx, half4(_785).yyy, half3(float3(params.facet_f0))) * _804, min(((half3(float3(params.facet_f0)) * min(_1050 * (_1050 * _1048), half(65504.0))) * _804) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_873) * half(_873)) / fast::max(_859, 9.9999997473787516355514526367188e-05)) * half(_892)) * half(_892)), float3(65504.0))) * _953), half3(float3(65504.0)))) + min(((half3(float3(params.facet_f0)) * min(_1311 * (_1311 * _1309), half(65504.0))) * _804) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1134) * half(_1134)) / fast::max(_1120, 9.9999997473787516355514526367188e-05)) * half(_1153)) * half(_1153)), float3(65504.0))) * _1214), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1342, half(1.0)));
    return out;
}

