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
    half3 _635 = normalize(half3(in.v_normal));
    float3 _651 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _823 = max(dot(_635, half3(_651)), half(9.9999997473787516355514526367188e-05));
    half3 _827 = reflect(-half3(_651), _635);
    float4 _863 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_823, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _892 = facet_environment.sample(facet_environmentSmplr, float3(_827), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _842 = mix(half4(_863).xxx, half4(_863).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_863).y) - half(1.0))));
    float3 _937 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _940 = dot(_937, _937);
    float3 _945 = _937 * rsqrt(fast::max(_940, 9.9999999392252902907785028219223e-09));
    float _949 = _940 * float(frame.punctualLights[0].positionFalloff.w);
    float _954 = fast::clamp(fma(-_949, _949, 1.0), 0.0, 1.0);
    float _973 = fast::clamp(fma(dot(-_945, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1105 = clamp(dot(_827, half3(_945)), half(0.0), half(1.0));
    half _1108 = _1105 * _1105;
    half4 _1612 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1108 * _1108, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1120 = _1612.x;
    float3 _1165 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1168 = dot(_1165, _1165);
    float3 _1173 = _1165 * rsqrt(fast::max(_1168, 9.9999999392252902907785028219223e-09));
    float _1177 = _1168 * float(frame.punctualLights[1].positionFalloff.w);
    float _1182 = fast::clamp(fma(-_1177, _1177, 1.0), 0.0, 1.0);
    float _1201 = fast::clamp(fma(dot(-_1173, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1333 = clamp(dot(_827, half3(_1173)), half(0.0), half(1.0));
    half _1336 = _1333 * _1333;
    half4 _1638 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1336 * _1336, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1348 = _1638.x;
    half _1396 = half(1.0) - _823;
    half _1399 = _1396 * _1396;
    half _1416 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1426 = facet_environment.sample(facet_environmentSmplr, float3(_827), level(_1416 * (half(4.0) * (half(2.0) - _1416))));
    half3 _1390 = mix(fma(half4(_892).xyz, _842, min((_842 * ((_1120 * _1120) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_954) * half(_954)) / fast::max(_940, 9.9999997473787516355514526367188e-05)) * half(_973)) * half(_973)), float3(65504.0))) * clamp(dot(_635, half3(_945)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_842 * ((_1348 * _1348) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1182) * half(_1182)) / fast::max(_1168, 9.9999997473787516355514526367188e-05)) * half(_1201)) * half(_1201)), float3(65504.0))) * clamp(dot(_635, half3(_1173)), half(0.0), half(1.0))), half3(float3(65504.0))), half4(_1426).xyz, half3(fma(half(0.959999978542327880859375), (_1399 * _1399) * _1396, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_1390, half(1.0)));
    return out;
}

