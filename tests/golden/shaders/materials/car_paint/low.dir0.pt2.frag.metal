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
    float facet_clearCoat;
    float facet_clearCoatAlpha;
    float facet_clearCoatLod;
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
    half3 _625 = normalize(half3(in.v_normal));
    float3 _641 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _814 = max(dot(_625, half3(_641)), half(9.9999997473787516355514526367188e-05));
    half3 _818 = reflect(-half3(_641), _625);
    float4 _854 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_814, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _883 = facet_environment.sample(facet_environmentSmplr, float3(_818), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _833 = mix(half4(_854).xxx, half4(_854).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_854).y) - half(1.0))));
    float3 _928 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _931 = dot(_928, _928);
    float3 _936 = _928 * rsqrt(fast::max(_931, 9.9999999392252902907785028219223e-09));
    float _940 = _931 * float(frame.punctualLights[0].positionFalloff.w);
    float _945 = fast::clamp(fma(-_940, _940, 1.0), 0.0, 1.0);
    float _964 = fast::clamp(fma(dot(-_936, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1096 = clamp(dot(_818, half3(_936)), half(0.0), half(1.0));
    half _1099 = _1096 * _1096;
    half4 _1581 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1099 * _1099, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1111 = _1581.x;
    float3 _1156 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1159 = dot(_1156, _1156);
    float3 _1164 = _1156 * rsqrt(fast::max(_1159, 9.9999999392252902907785028219223e-09));
    float _1168 = _1159 * float(frame.punctualLights[1].positionFalloff.w);
    float _1173 = fast::clamp(fma(-_1168, _1168, 1.0), 0.0, 1.0);
    float _1192 = fast::clamp(fma(dot(-_1164, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1324 = clamp(dot(_818, half3(_1164)), half(0.0), half(1.0));
    half _1327 = _1324 * _1324;
    half4 _1607 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1327 * _1327, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1339 = _1607.x;
    half _1386 = half(1.0) - _814;
    half _1389 = _1386 * _1386;
    float4 _1374 = facet_environment.sample(facet_environmentSmplr, float3(_818), level(params.facet_clearCoatLod));
    half3 _1380 = mix(fma(half4(_883).xyz, _833, min((_833 * ((_1111 * _1111) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_945) * half(_945)) / fast::max(_931, 9.9999997473787516355514526367188e-05)) * half(_964)) * half(_964)), float3(65504.0))) * clamp(dot(_625, half3(_936)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_833 * ((_1339 * _1339) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1173) * half(_1173)) / fast::max(_1159, 9.9999997473787516355514526367188e-05)) * half(_1192)) * half(_1192)), float3(65504.0))) * clamp(dot(_625, half3(_1164)), half(0.0), half(1.0))), half3(float3(65504.0))), half4(_1374).xyz, half3(fma(half(0.959999978542327880859375), (_1389 * _1389) * _1386, half(0.039999999105930328369140625)) * half(params.facet_clearCoat)));
    out.fragColor = float4(half4(_1380, half(1.0)));
    return out;
}

