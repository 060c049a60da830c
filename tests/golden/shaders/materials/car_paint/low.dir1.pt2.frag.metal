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
    half _844 = max(dot(_635, half3(_651)), half(9.9999997473787516355514526367188e-05));
    half3 _848 = reflect(-half3(_651), _635);
    float4 _884 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_844, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _913 = facet_environment.sample(facet_environmentSmplr, float3(_848), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _863 = mix(half4(_884).xxx, half4(_884).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_884).y) - half(1.0))));
    half3 _689 = half4(frame.lightDirection).xyz;
    half _1042 = clamp(dot(_848, _689), half(0.0), half(1.0));
    half _1045 = _1042 * _1042;
    half4 _1766 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1045 * _1045, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1057 = _1766.x;
    float3 _1102 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1105 = dot(_1102, _1102);
    float3 _1110 = _1102 * rsqrt(fast::max(_1105, 9.9999999392252902907785028219223e-09));
    float _1114 = _1105 * float(frame.punctualLights[0].positionFalloff.w);
    float _1119 = fast::clamp(fma(-_1114, _1114, 1.0), 0.0, 1.0);
    float _1138 = fast::clamp(fma(dot(-_1110, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1270 = clamp(dot(_848, half3(_1110)), half(0.0), half(1.0));
    half _1273 = _1270 * _1270;
    half4 _1791 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1273 * _1273, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1285 = _1791.x;
    float3 _1330 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1333 = dot(_1330, _1330);
    float3 _1338 = _1330 * rsqrt(fast::max(_1333, 9.9999999392252902907785028219223e-09));
    float _1342 = _1333 * float(frame.punctualLights[1].positionFalloff.w);
    float _1347 = fast::clamp(fma(-_1342, _1342, 1.0), 0.0, 1.0);
    float _1366 = fast::clamp(fma(dot(-_1338, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1498 = clamp(dot(_848, half3(_1338)), half(0.0), half(1.0));
    half _1501 = _1498 * _1498;
    half4 _1817 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1501 * _1501, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1513 = _1817.x;
    half3 _1522 = (fma(half4(_913).xyz, _863, min((_863 * ((_1057 * _1057) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_635, _689), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_863 * ((_1285 * _1285) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1119) * half(_1119)) / fast::max(_1105, 9.9999997473787516355514526367188e-05)) * half(_1138)) * half(_1138)), float3(65504.0))) * clamp(dot(_635, half3(_1110)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_863 * ((_1513 * _1513) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1347) * half(_1347)) / fast::max(_1333, 9.9999997473787516355514526367188e-05)) * half(_1366)) * half(_1366)), float3(65504.0))) * clamp(dot(_635, half3(_1338)), half(0.0), half(1.0))), half3(float3(65504.0)));
    half _1561 = half(1.0) - _844;
    half _1564 = _1561 * _1561;
    half _1581 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1591 = facet_environment.sample(facet_environmentSmplr, float3(_848), level(_1581 * (half(4.0) * (half(2.0) - _1581))));
    out.fragColor = float4(half4(mix(_1522, half4(_1591).xyz, half3(fma(half(0.959999978542327880859375), (_1564 * _1564) * _1561, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0)))), half(1.0)));
    return out;
}

