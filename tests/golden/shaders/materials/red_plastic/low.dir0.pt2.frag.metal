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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
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
    half3 _501 = normalize(half3(in.v_normal));
    float3 _517 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _668 = reflect(-half3(_517), _501);
    float4 _701 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_501, half3(_517)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    half3 _710 = mix(half4(_701).xxx, half4(_701).yyy, half3(float3(params.facet_f0)));
    float4 _679 = facet_environment.sample(facet_environmentSmplr, float3(_668), level(params.facet_environmentLod));
    float3 _754 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _757 = dot(_754, _754);
    float3 _762 = _754 * rsqrt(fast::max(_757, 9.9999999392252902907785028219223e-09));
    float _766 = _757 * float(frame.punctualLights[0].positionFalloff.w);
    float _771 = fast::clamp(fma(-_766, _766, 1.0), 0.0, 1.0);
    float _790 = fast::clamp(fma(dot(-_762, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _922 = clamp(dot(_668, half3(_762)), half(0.0), half(1.0));
    half _925 = _922 * _922;
    half4 _1318 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_925 * _925, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _937 = _1318.x;
    float3 _982 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _985 = dot(_982, _982);
    float3 _990 = _982 * rsqrt(fast::max(_985, 9.9999999392252902907785028219223e-09));
    float _994 = _985 * float(frame.punctualLights[1].positionFalloff.w);
    float _999 = fast::clamp(fma(-_994, _994, 1.0), 0.0, 1.0);
    float _1018 = fast::clamp(fma(dot(-_990, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1150 = clamp(dot(_668, half3(_990)), half(0.0), half(1.0));
    half _1153 = _1150 * _1150;
    half4 _1344 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1153 * _1153, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1165 = _1344.x;
    half3 _1174 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_679).xyz * _710) + min((_710 * ((_937 * _937) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_771) * half(_771)) / fast::max(_757, 9.9999997473787516355514526367188e-05)) * half(_790)) * half(_790)), float3(65504.0))) * clamp(dot(_501, half3(_762)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_710 * ((_1165 * _1165) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_999) * half(_999)) / fast::max(_985, 9.9999997473787516355514526367188e-05)) * half(_1018)) * half(_1018)), float3(65504.0))) * clamp(dot(_501, half3(_990)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1174, half(1.0)));
    return out;
}

