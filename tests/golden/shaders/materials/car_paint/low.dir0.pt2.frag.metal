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
    half _822 = max(dot(_631, half3(_647)), half(9.9999997473787516355514526367188e-05));
    half3 _826 = reflect(-half3(_647), _631);
    float4 _862 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_822, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _888 = facet_environment.sample(facet_environmentSmplr, float3(_826), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _841 = mix(half4(_862).xxx, half4(_862).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_862).y) - half(1.0))));
    float3 _933 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _936 = dot(_933, _933);
    float3 _941 = _933 * rsqrt(fast::max(_936, 9.9999999392252902907785028219223e-09));
    float _945 = _936 * float(frame.punctualLights[0].positionFalloff.w);
    float _950 = fast::clamp(fma(-_945, _945, 1.0), 0.0, 1.0);
    float _969 = fast::clamp(fma(dot(-_941, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1101 = clamp(dot(_826, half3(_941)), half(0.0), half(1.0));
    half _1104 = _1101 * _1101;
    half4 _1603 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1104 * _1104, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1116 = _1603.x;
    float3 _1161 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1164 = dot(_1161, _1161);
    float3 _1169 = _1161 * rsqrt(fast::max(_1164, 9.9999999392252902907785028219223e-09));
    float _1173 = _1164 * float(frame.punctualLights[1].positionFalloff.w);
    float _1178 = fast::clamp(fma(-_1173, _1173, 1.0), 0.0, 1.0);
    float _1197 = fast::clamp(fma(dot(-_1169, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1329 = clamp(dot(_826, half3(_1169)), half(0.0), half(1.0));
    half _1332 = _1329 * _1329;
    half4 _1629 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1332 * _1332, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1344 = _1629.x;
    half _1392 = half(1.0) - _822;
    half _1395 = _1392 * _1392;
    float4 _1419 = facet_environment.sample(facet_environmentSmplr, float3(_826), level(clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0)) * half(4.0)));
    half3 _1386 = mix(fma(half4(_888).xyz, _841, min((_841 * ((_1116 * _1116) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_950) * half(_950)) / fast::max(_936, 9.9999997473787516355514526367188e-05)) * half(_969)) * half(_969)), float3(65504.0))) * clamp(dot(_631, half3(_941)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_841 * ((_1344 * _1344) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1178) * half(_1178)) / fast::max(_1164, 9.9999997473787516355514526367188e-05)) * half(_1197)) * half(_1197)), float3(65504.0))) * clamp(dot(_631, half3(_1169)), half(0.0), half(1.0))), half3(float3(65504.0))), half4(_1419).xyz, half3(fma(half(0.959999978542327880859375), (_1395 * _1395) * _1392, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_1386, half(1.0)));
    return out;
}

