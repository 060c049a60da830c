#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 baseColor;
    float roughness;
    float reflectance;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    packed_float3 facet_diffuseColor;
    float facet_perceptualRoughness;
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
    float3 v_diffuseLight [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _513 = normalize(half3(in.v_normal));
    float3 _529 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _682 = reflect(-half3(_529), _513);
    float4 _712 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_513, half3(_529)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    half3 _721 = mix(half4(_712).xxx, half4(_712).yyy, half3(float3(params.facet_f0)));
    float4 _728 = facet_environment.sample(facet_environmentSmplr, float3(_682), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _773 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _776 = dot(_773, _773);
    float3 _781 = _773 * rsqrt(fast::max(_776, 9.9999999392252902907785028219223e-09));
    float _785 = _776 * float(frame.punctualLights[0].positionFalloff.w);
    float _790 = fast::clamp(fma(-_785, _785, 1.0), 0.0, 1.0);
    float _809 = fast::clamp(fma(dot(-_781, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _941 = clamp(dot(_682, half3(_781)), half(0.0), half(1.0));
    half _944 = _941 * _941;
    half4 _1339 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_944 * _944, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _956 = _1339.x;
    float3 _1001 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1004 = dot(_1001, _1001);
    float3 _1009 = _1001 * rsqrt(fast::max(_1004, 9.9999999392252902907785028219223e-09));
    float _1013 = _1004 * float(frame.punctualLights[1].positionFalloff.w);
    float _1018 = fast::clamp(fma(-_1013, _1013, 1.0), 0.0, 1.0);
    float _1037 = fast::clamp(fma(dot(-_1009, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1169 = clamp(dot(_682, half3(_1009)), half(0.0), half(1.0));
    half _1172 = _1169 * _1169;
    half4 _1365 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1172 * _1172, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1184 = _1365.x;
    half3 _1193 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_728).xyz * _721) + min((_721 * ((_956 * _956) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_790) * half(_790)) / fast::max(_776, 9.9999997473787516355514526367188e-05)) * half(_809)) * half(_809)), float3(65504.0))) * clamp(dot(_513, half3(_781)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_721 * ((_1184 * _1184) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1018) * half(_1018)) / fast::max(_1004, 9.9999997473787516355514526367188e-05)) * half(_1037)) * half(_1037)), float3(65504.0))) * clamp(dot(_513, half3(_1009)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1193, half(1.0)));
    return out;
}

