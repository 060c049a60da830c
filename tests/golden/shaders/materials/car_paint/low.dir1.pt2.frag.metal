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
    half _840 = max(dot(_631, half3(_647)), half(9.9999997473787516355514526367188e-05));
    half3 _844 = reflect(-half3(_647), _631);
    float4 _880 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_840, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _906 = facet_environment.sample(facet_environmentSmplr, float3(_844), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _859 = mix(half4(_880).xxx, half4(_880).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_880).y) - half(1.0))));
    half3 _685 = half4(frame.lightDirection).xyz;
    half _1035 = clamp(dot(_844, _685), half(0.0), half(1.0));
    half _1038 = _1035 * _1035;
    half4 _1754 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1038 * _1038, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1050 = _1754.x;
    float3 _1095 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1098 = dot(_1095, _1095);
    float3 _1103 = _1095 * rsqrt(fast::max(_1098, 9.9999999392252902907785028219223e-09));
    float _1107 = _1098 * float(frame.punctualLights[0].positionFalloff.w);
    float _1112 = fast::clamp(fma(-_1107, _1107, 1.0), 0.0, 1.0);
    float _1131 = fast::clamp(fma(dot(-_1103, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1263 = clamp(dot(_844, half3(_1103)), half(0.0), half(1.0));
    half _1266 = _1263 * _1263;
    half4 _1779 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1266 * _1266, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1278 = _1779.x;
    float3 _1323 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1326 = dot(_1323, _1323);
    float3 _1331 = _1323 * rsqrt(fast::max(_1326, 9.9999999392252902907785028219223e-09));
    float _1335 = _1326 * float(frame.punctualLights[1].positionFalloff.w);
    float _1340 = fast::clamp(fma(-_1335, _1335, 1.0), 0.0, 1.0);
    float _1359 = fast::clamp(fma(dot(-_1331, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1491 = clamp(dot(_844, half3(_1331)), half(0.0), half(1.0));
    half _1494 = _1491 * _1491;
    half4 _1805 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1494 * _1494, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1506 = _1805.x;
    half3 _1515 = (fma(half4(_906).xyz, _859, min((_859 * ((_1050 * _1050) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_631, _685), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_859 * ((_1278 * _1278) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1112) * half(_1112)) / fast::max(_1098, 9.9999997473787516355514526367188e-05)) * half(_1131)) * half(_1131)), float3(65504.0))) * clamp(dot(_631, half3(_1103)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_859 * ((_1506 * _1506) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1340) * half(_1340)) / fast::max(_1326, 9.9999997473787516355514526367188e-05)) * half(_1359)) * half(_1359)), float3(65504.0))) * clamp(dot(_631, half3(_1331)), half(0.0), half(1.0))), half3(float3(65504.0)));
    half _1554 = half(1.0) - _840;
    half _1557 = _1554 * _1554;
    float4 _1581 = facet_environment.sample(facet_environmentSmplr, float3(_844), level(clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0)) * half(4.0)));
    half3 _1548 = mix(_1515, half4(_1581).xyz, half3(fma(half(0.959999978542327880859375), (_1557 * _1557) * _1554, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_1548, half(1.0)));
    return out;
}

