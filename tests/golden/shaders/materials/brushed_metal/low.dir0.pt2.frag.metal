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
    float4 v_tangent [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _656 = normalize(half3(in.v_normal));
    float3 _672 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _796 = half4(in.v_tangent).xyz;
    half _849 = max(dot(_656, half3(_672)), half(9.9999997473787516355514526367188e-05));
    half _959 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half3 _1582;
    if (float(_959) >= 0.0)
    {
        _1582 = _796;
    }
    else
    {
        _1582 = cross(_656, _796);
    }
    half _910 = dot(_1582, half3(_672));
    half _917 = min(abs(_959) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _922 = fma(half(-float(_917)), half(1.0) - _849, half(1.0));
    half _925 = _917 * _910;
    half _941 = (half(2.0) * fma(_922, _849, _925 * _910)) / fma(_922, _922, _925 * _925);
    float4 _966 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_849, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _992 = facet_environment.sample(facet_environmentSmplr, float3((((_656 * (_922 * _941)) + (_1582 * (_925 * _941))) - half3(_672))), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _870 = mix(half4(_966).xxx, half4(_966).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_966).y) - half(1.0))));
    float3 _1037 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1040 = dot(_1037, _1037);
    float3 _1045 = _1037 * rsqrt(fast::max(_1040, 9.9999999392252902907785028219223e-09));
    float _1049 = _1040 * float(frame.punctualLights[0].positionFalloff.w);
    float _1054 = fast::clamp(fma(-_1049, _1049, 1.0), 0.0, 1.0);
    float _1073 = fast::clamp(fma(dot(-_1045, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1189 = reflect(-half3(_672), _656);
    half _1205 = clamp(dot(_1189, half3(_1045)), half(0.0), half(1.0));
    half _1208 = _1205 * _1205;
    half4 _1654 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1208 * _1208, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1220 = _1654.x;
    float3 _1265 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1268 = dot(_1265, _1265);
    float3 _1273 = _1265 * rsqrt(fast::max(_1268, 9.9999999392252902907785028219223e-09));
    float _1277 = _1268 * float(frame.punctualLights[1].positionFalloff.w);
    float _1282 = fast::clamp(fma(-_1277, _1277, 1.0), 0.0, 1.0);
    float _1301 = fast::clamp(fma(dot(-_1273, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1433 = clamp(dot(_1189, half3(_1273)), half(0.0), half(1.0));
    half _1436 = _1433 * _1433;
    half4 _1680 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1436 * _1436, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1448 = _1680.x;
    half3 _1457 = fma(half4(_992).xyz, _870, min((_870 * ((_1220 * _1220) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1054) * half(_1054)) / fast::max(_1040, 9.9999997473787516355514526367188e-05)) * half(_1073)) * half(_1073)), float3(65504.0))) * clamp(dot(_656, half3(_1045)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_870 * ((_1448 * _1448) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1282) * half(_1282)) / fast::max(_1268, 9.9999997473787516355514526367188e-05)) * half(_1301)) * half(_1301)), float3(65504.0))) * clamp(dot(_656, half3(_1273)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1457, half(1.0)));
    return out;
}

