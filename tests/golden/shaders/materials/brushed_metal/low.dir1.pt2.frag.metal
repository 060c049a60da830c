#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float anisotropy;
    float facet_pad20;
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
    half3 _553 = normalize(half3(in.v_normal));
    float3 _569 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _755 = reflect(-half3(_569), _553);
    float4 _791 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_553, half3(_569)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _822 = facet_environment.sample(facet_environmentSmplr, float3(_755), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _770 = mix(half4(_791).xxx, half4(_791).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_791).y) - half(1.0))));
    half3 _606 = half4(frame.lightDirection).xyz;
    half _951 = clamp(dot(_755, _606), half(0.0), half(1.0));
    half _954 = _951 * _951;
    half4 _1596 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_954 * _954, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _966 = _1596.x;
    float3 _1011 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1014 = dot(_1011, _1011);
    float3 _1019 = _1011 * rsqrt(fast::max(_1014, 9.9999999392252902907785028219223e-09));
    float _1023 = _1014 * float(frame.punctualLights[0].positionFalloff.w);
    float _1028 = fast::clamp(fma(-_1023, _1023, 1.0), 0.0, 1.0);
    float _1047 = fast::clamp(fma(dot(-_1019, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1179 = clamp(dot(_755, half3(_1019)), half(0.0), half(1.0));
    half _1182 = _1179 * _1179;
    half4 _1621 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1182 * _1182, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1194 = _1621.x;
    float3 _1239 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1242 = dot(_1239, _1239);
    float3 _1247 = _1239 * rsqrt(fast::max(_1242, 9.9999999392252902907785028219223e-09));
    float _1251 = _1242 * float(frame.punctualLights[1].positionFalloff.w);
    float _1256 = fast::clamp(fma(-_1251, _1251, 1.0), 0.0, 1.0);
    float _1275 = fast::clamp(fma(dot(-_1247, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1407 = clamp(dot(_755, half3(_1247)), half(0.0), half(1.0));
    half _1410 = _1407 * _1407;
    half4 _1647 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1410 * _1410, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1422 = _1647.x;
    half3 _1431 = (fma(half4(_822).xyz, _770, min((_770 * ((_966 * _966) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_553, _606), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_770 * ((_1194 * _1194) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1028) * half(_1028)) / fast::max(_1014, 9.9999997473787516355514526367188e-05)) * half(_1047)) * half(_1047)), float3(65504.0))) * clamp(dot(_553, half3(_1019)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_770 * ((_1422 * _1422) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1256) * half(_1256)) / fast::max(_1242, 9.9999997473787516355514526367188e-05)) * half(_1275)) * half(_1275)), float3(65504.0))) * clamp(dot(_553, half3(_1247)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1431, half(1.0)));
    return out;
}

