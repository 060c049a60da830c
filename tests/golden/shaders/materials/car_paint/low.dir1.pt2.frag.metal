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
    half _843 = max(dot(_631, half3(_647)), half(9.9999997473787516355514526367188e-05));
    half3 _847 = reflect(-half3(_647), _631);
    float4 _883 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_843, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _909 = facet_environment.sample(facet_environmentSmplr, float3(_847), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _862 = mix(half4(_883).xxx, half4(_883).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_883).y) - half(1.0))));
    half3 _685 = half4(frame.lightDirection).xyz;
    half _1038 = clamp(dot(_847, _685), half(0.0), half(1.0));
    half _1041 = _1038 * _1038;
    half4 _1757 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1041 * _1041, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1053 = _1757.x;
    float3 _1098 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1101 = dot(_1098, _1098);
    float3 _1106 = _1098 * rsqrt(fast::max(_1101, 9.9999999392252902907785028219223e-09));
    float _1110 = _1101 * float(frame.punctualLights[0].positionFalloff.w);
    float _1115 = fast::clamp(fma(-_1110, _1110, 1.0), 0.0, 1.0);
    float _1134 = fast::clamp(fma(dot(-_1106, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1266 = clamp(dot(_847, half3(_1106)), half(0.0), half(1.0));
    half _1269 = _1266 * _1266;
    half4 _1782 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1269 * _1269, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1281 = _1782.x;
    float3 _1326 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1329 = dot(_1326, _1326);
    float3 _1334 = _1326 * rsqrt(fast::max(_1329, 9.9999999392252902907785028219223e-09));
    float _1338 = _1329 * float(frame.punctualLights[1].positionFalloff.w);
    float _1343 = fast::clamp(fma(-_1338, _1338, 1.0), 0.0, 1.0);
    float _1362 = fast::clamp(fma(dot(-_1334, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1494 = clamp(dot(_847, half3(_1334)), half(0.0), half(1.0));
    half _1497 = _1494 * _1494;
    half4 _1808 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1497 * _1497, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1509 = _1808.x;
    half3 _1518 = (fma(half4(_909).xyz, _862, min((_862 * ((_1053 * _1053) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_631, _685), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_862 * ((_1281 * _1281) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1115) * half(_1115)) / fast::max(_1101, 9.9999997473787516355514526367188e-05)) * half(_1134)) * half(_1134)), float3(65504.0))) * clamp(dot(_631, half3(_1106)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_862 * ((_1509 * _1509) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1343) * half(_1343)) / fast::max(_1329, 9.9999997473787516355514526367188e-05)) * half(_1362)) * half(_1362)), float3(65504.0))) * clamp(dot(_631, half3(_1334)), half(0.0), half(1.0))), half3(float3(65504.0)));
    half _1557 = half(1.0) - _843;
    half _1560 = _1557 * _1557;
    float4 _1584 = facet_environment.sample(facet_environmentSmplr, float3(_847), level(clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0)) * half(4.0)));
    half3 _1551 = mix(_1518, half4(_1584).xyz, half3(fma(half(0.959999978542327880859375), (_1560 * _1560) * _1557, half(0.039999999105930328369140625)) * clamp(half(params.coat), half(0.0), half(1.0))));
    out.fragColor = float4(half4(_1551, half(1.0)));
    return out;
}

