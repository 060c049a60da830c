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
    half3 _640 = normalize(half3(in.v_normal));
    float3 _656 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _849 = max(dot(_640, half3(_656)), half(9.9999997473787516355514526367188e-05));
    half3 _853 = reflect(-half3(_656), _640);
    float4 _889 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_849, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _918 = facet_environment.sample(facet_environmentSmplr, float3(_853), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _868 = mix(half4(_889).xxx, half4(_889).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_889).y) - half(1.0))));
    half3 _694 = half4(frame.lightDirection).xyz;
    half _1047 = clamp(dot(_853, _694), half(0.0), half(1.0));
    half _1050 = _1047 * _1047;
    half4 _1775 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1050 * _1050, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1062 = _1775.x;
    float3 _1107 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1110 = dot(_1107, _1107);
    float3 _1115 = _1107 * rsqrt(fast::max(_1110, 9.9999999392252902907785028219223e-09));
    float _1119 = _1110 * float(frame.punctualLights[0].positionFalloff.w);
    float _1124 = fast::clamp(fma(-_1119, _1119, 1.0), 0.0, 1.0);
    float _1143 = fast::clamp(fma(dot(-_1115, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1275 = clamp(dot(_853, half3(_1115)), half(0.0), half(1.0));
    half _1278 = _1275 * _1275;
    half4 _1800 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1278 * _1278, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1290 = _1800.x;
    float3 _1335 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1338 = dot(_1335, _1335);
    float3 _1343 = _1335 * rsqrt(fast::max(_1338, 9.9999999392252902907785028219223e-09));
    float _1347 = _1338 * float(frame.punctualLights[1].positionFalloff.w);
    float _1352 = fast::clamp(fma(-_1347, _1347, 1.0), 0.0, 1.0);
    float _1371 = fast::clamp(fma(dot(-_1343, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1503 = clamp(dot(_853, half3(_1343)), half(0.0), half(1.0));
    half _1506 = _1503 * _1503;
    half4 _1826 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1506 * _1506, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1518 = _1826.x;
    half3 _1527 = (fma(half4(_918).xyz, _868, min((_868 * ((_1062 * _1062) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_640, _694), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_868 * ((_1290 * _1290) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1124) * half(_1124)) / fast::max(_1110, 9.9999997473787516355514526367188e-05)) * half(_1143)) * half(_1143)), float3(65504.0))) * clamp(dot(_640, half3(_1115)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_868 * ((_1518 * _1518) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1352) * half(_1352)) / fast::max(_1338, 9.9999997473787516355514526367188e-05)) * half(_1371)) * half(_1371)), float3(65504.0))) * clamp(dot(_640, half3(_1343)), half(0.0), half(1.0))), half3(float3(65504.0)));
    half _1565 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1571 = half(1.0) - _849;
    half _1574 = _1571 * _1571;
    half _1590 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1600 = facet_environment.sample(facet_environmentSmplr, float3(_853), level(_1590 * (half(4.0) * (half(2.0) - _1590))));
    out.fragColor = float4(half4(mix(_1527, half4(_1600).xyz, half3(fma(half(0.039999999105930328369140625), _1565, (half(0.959999978542327880859375) * _1565) * ((_1574 * _1574) * _1571)))), half(1.0)));
    return out;
}

