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
    half3 _547 = normalize(half3(in.v_normal));
    float3 _563 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _728 = reflect(-half3(_563), _547);
    float4 _764 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_547, half3(_563)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _790 = facet_environment.sample(facet_environmentSmplr, float3(_728), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _743 = mix(half4(_764).xxx, half4(_764).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_764).y) - half(1.0))));
    float3 _835 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _838 = dot(_835, _835);
    float3 _843 = _835 * rsqrt(fast::max(_838, 9.9999999392252902907785028219223e-09));
    float _847 = _838 * float(frame.punctualLights[0].positionFalloff.w);
    float _852 = fast::clamp(fma(-_847, _847, 1.0), 0.0, 1.0);
    float _871 = fast::clamp(fma(dot(-_843, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1003 = clamp(dot(_728, half3(_843)), half(0.0), half(1.0));
    half _1006 = _1003 * _1003;
    half4 _1429 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1006 * _1006, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1018 = _1429.x;
    float3 _1063 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1066 = dot(_1063, _1063);
    float3 _1071 = _1063 * rsqrt(fast::max(_1066, 9.9999999392252902907785028219223e-09));
    float _1075 = _1066 * float(frame.punctualLights[1].positionFalloff.w);
    float _1080 = fast::clamp(fma(-_1075, _1075, 1.0), 0.0, 1.0);
    float _1099 = fast::clamp(fma(dot(-_1071, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1231 = clamp(dot(_728, half3(_1071)), half(0.0), half(1.0));
    half _1234 = _1231 * _1231;
    half4 _1455 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1234 * _1234, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1246 = _1455.x;
    half3 _1255 = fma(half4(_790).xyz, _743, min((_743 * ((_1018 * _1018) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_852) * half(_852)) / fast::max(_838, 9.9999997473787516355514526367188e-05)) * half(_871)) * half(_871)), float3(65504.0))) * clamp(dot(_547, half3(_843)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_743 * ((_1246 * _1246) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1080) * half(_1080)) / fast::max(_1066, 9.9999997473787516355514526367188e-05)) * half(_1099)) * half(_1099)), float3(65504.0))) * clamp(dot(_547, half3(_1071)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1255, half(1.0)));
    return out;
}

