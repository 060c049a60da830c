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
    half _828 = max(dot(_640, half3(_656)), half(9.9999997473787516355514526367188e-05));
    half3 _832 = reflect(-half3(_656), _640);
    float4 _868 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_828, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _897 = facet_environment.sample(facet_environmentSmplr, float3(_832), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _847 = mix(half4(_868).xxx, half4(_868).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_868).y) - half(1.0))));
    float3 _942 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _945 = dot(_942, _942);
    float3 _950 = _942 * rsqrt(fast::max(_945, 9.9999999392252902907785028219223e-09));
    float _954 = _945 * float(frame.punctualLights[0].positionFalloff.w);
    float _959 = fast::clamp(fma(-_954, _954, 1.0), 0.0, 1.0);
    float _978 = fast::clamp(fma(dot(-_950, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1110 = clamp(dot(_832, half3(_950)), half(0.0), half(1.0));
    half _1113 = _1110 * _1110;
    half4 _1621 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1113 * _1113, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1125 = _1621.x;
    float3 _1170 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1173 = dot(_1170, _1170);
    float3 _1178 = _1170 * rsqrt(fast::max(_1173, 9.9999999392252902907785028219223e-09));
    float _1182 = _1173 * float(frame.punctualLights[1].positionFalloff.w);
    float _1187 = fast::clamp(fma(-_1182, _1182, 1.0), 0.0, 1.0);
    float _1206 = fast::clamp(fma(dot(-_1178, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1338 = clamp(dot(_832, half3(_1178)), half(0.0), half(1.0));
    half _1341 = _1338 * _1338;
    half4 _1647 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1341 * _1341, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1353 = _1647.x;
    half _1400 = clamp(half(params.coat), half(0.0), half(1.0));
    half _1406 = half(1.0) - _828;
    half _1409 = _1406 * _1406;
    half _1425 = clamp(half(params.coatRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1435 = facet_environment.sample(facet_environmentSmplr, float3(_832), level(_1425 * (half(4.0) * (half(2.0) - _1425))));
    half3 _1395 = mix(fma(half4(_897).xyz, _847, min((_847 * ((_1125 * _1125) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_959) * half(_959)) / fast::max(_945, 9.9999997473787516355514526367188e-05)) * half(_978)) * half(_978)), float3(65504.0))) * clamp(dot(_640, half3(_950)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_847 * ((_1353 * _1353) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1187) * half(_1187)) / fast::max(_1173, 9.9999997473787516355514526367188e-05)) * half(_1206)) * half(_1206)), float3(65504.0))) * clamp(dot(_640, half3(_1178)), half(0.0), half(1.0))), half3(float3(65504.0))), half4(_1435).xyz, half3(fma(half(0.039999999105930328369140625), _1400, (half(0.959999978542327880859375) * _1400) * ((_1409 * _1409) * _1406))));
    out.fragColor = float4(half4(_1395, half(1.0)));
    return out;
}

