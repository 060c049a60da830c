#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _631 = normalize(half3(in.v_normal));
    float3 _647 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _819 = max(dot(_631, half3(_647)), half(9.9999997473787516355514526367188e-05));
    half3 _823 = reflect(-half3(_647), _631);
    float4 _859 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_819, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _885 = facet_environment.sample(facet_environmentSmplr, float3(_823), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _838 = mix(half4(_859).xxx, half4(_859).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_859).y) - half(1.0))));
    float3 _930 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _933 = dot(_930, _930);
    float3 _938 = _930 * rsqrt(fast::max(_933, 9.9999999392252902907785028219223e-09));
    float _942 = _933 * float(frame.punctualLights[0].positionFalloff.w);
    float _947 = fast::clamp(fma(-_942, _942, 1.0), 0.0, 1.0);
    float _966 = fast::clamp(fma(dot(-_938, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1098 = clamp(dot(_823, half3(_938)), half(0.0), half(1.0));
    half _1101 = _1098 * _1098;
    half4 _1600 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1101 * _1101, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1113 = _1600.x;
    float3 _1158 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1161 = dot(_1158, _1158);
    float3 _1166 = _1158 * rsqrt(fast::max(_1161, 9.9999999392252902907785028219223e-09));
    float _1170 = _1161 * float(frame.punctualLights[1].positionFalloff.w);
    float _1175 = fast::clamp(fma(-_1170, _1170, 1.0), 0.0, 1.0);
    float _1194 = fast::clamp(fma(dot(-_1166, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1326 = clamp(dot(_823, half3(_1166)), half(0.0), half(1.0));
    half _1329 = _1326 * _1326;
    half4 _1626 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1329 * _1329, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1341 = _1626.x;
    half _1389 = half(1.0) - _819;
    half _1392 = _1389 * _1389;
    float4 _1416 = facet_environment.sample(facet_environmentSmplr, float3(_823), level(clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0)) * half(4.0)));
    half3 _1383 = mix(fma(half4(_885).xyz, _838, min((_838 * ((_1113 * _1113) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_947) * half(_947)) / fast::max(_933, 9.9999997473787516355514526367188e-05)) * half(_966)) * half(_966)), float3(65504.0))) * clamp(dot(_631, half3(_938)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_838 * ((_1341 * _1341) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1175) * half(_1175)) / fast::max(_1161, 9.9999997473787516355514526367188e-05)) * half(_1194)) * half(_1194)), float3(65504.0))) * clamp(dot(_631, half3(_1166)), half(0.0), half(1.0))), half3(float3(65504.0))), half4(_1416).xyz, half3(fma(half(0.959999978542327880859375), (_1392 * _1392) * _1389, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_1383, half(1.0)));
    return out;
}

