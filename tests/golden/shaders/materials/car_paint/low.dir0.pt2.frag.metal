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
    half3 _637 = normalize(half3(in.v_normal));
    float3 _653 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _825 = max(dot(_637, half3(_653)), half(9.9999997473787516355514526367188e-05));
    half3 _829 = reflect(-half3(_653), _637);
    float4 _865 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_825, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _896 = facet_environment.sample(facet_environmentSmplr, float3(_829), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _844 = mix(half4(_865).xxx, half4(_865).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_865).y) - half(1.0))));
    float3 _941 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _944 = dot(_941, _941);
    float3 _949 = _941 * rsqrt(fast::max(_944, 9.9999999392252902907785028219223e-09));
    float _953 = _944 * float(frame.punctualLights[0].positionFalloff.w);
    float _958 = fast::clamp(fma(-_953, _953, 1.0), 0.0, 1.0);
    float _977 = fast::clamp(fma(dot(-_949, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1109 = clamp(dot(_829, half3(_949)), half(0.0), half(1.0));
    half _1112 = _1109 * _1109;
    half4 _1618 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1112 * _1112, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1124 = _1618.x;
    float3 _1169 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1172 = dot(_1169, _1169);
    float3 _1177 = _1169 * rsqrt(fast::max(_1172, 9.9999999392252902907785028219223e-09));
    float _1181 = _1172 * float(frame.punctualLights[1].positionFalloff.w);
    float _1186 = fast::clamp(fma(-_1181, _1181, 1.0), 0.0, 1.0);
    float _1205 = fast::clamp(fma(dot(-_1177, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1337 = clamp(dot(_829, half3(_1177)), half(0.0), half(1.0));
    half _1340 = _1337 * _1337;
    half4 _1644 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1340 * _1340, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1352 = _1644.x;
    half _1400 = half(1.0) - _825;
    half _1403 = _1400 * _1400;
    half _1420 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1432 = facet_environment.sample(facet_environmentSmplr, float3(_829), level(_1420 * (half(4.0) * (half(2.0) - _1420))));
    half3 _1394 = mix(fma(half4(_896).xyz, _844, min((_844 * ((_1124 * _1124) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_958) * half(_958)) / fast::max(_944, 9.9999997473787516355514526367188e-05)) * half(_977)) * half(_977)), float3(65504.0))) * clamp(dot(_637, half3(_949)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_844 * ((_1352 * _1352) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1186) * half(_1186)) / fast::max(_1172, 9.9999997473787516355514526367188e-05)) * half(_1205)) * half(_1205)), float3(65504.0))) * clamp(dot(_637, half3(_1177)), half(0.0), half(1.0))), half3(float3(65504.0))), half4(_1432).xyz, half3(fma(half(0.959999978542327880859375), (_1403 * _1403) * _1400, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_1394, half(1.0)));
    return out;
}

