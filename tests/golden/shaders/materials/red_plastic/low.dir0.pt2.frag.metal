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
    half3 _517 = normalize(half3(in.v_normal));
    float3 _533 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _686 = reflect(-half3(_533), _517);
    float4 _716 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_517, half3(_533)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    half3 _725 = mix(half4(_716).xxx, half4(_716).yyy, half3(float3(params.facet_f0)));
    float4 _735 = facet_environment.sample(facet_environmentSmplr, float3(_686), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _780 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _783 = dot(_780, _780);
    float3 _788 = _780 * rsqrt(fast::max(_783, 9.9999999392252902907785028219223e-09));
    float _792 = _783 * float(frame.punctualLights[0].positionFalloff.w);
    float _797 = fast::clamp(fma(-_792, _792, 1.0), 0.0, 1.0);
    float _816 = fast::clamp(fma(dot(-_788, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _948 = clamp(dot(_686, half3(_788)), half(0.0), half(1.0));
    half _951 = _948 * _948;
    half4 _1348 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_951 * _951, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _963 = _1348.x;
    float3 _1008 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1011 = dot(_1008, _1008);
    float3 _1016 = _1008 * rsqrt(fast::max(_1011, 9.9999999392252902907785028219223e-09));
    float _1020 = _1011 * float(frame.punctualLights[1].positionFalloff.w);
    float _1025 = fast::clamp(fma(-_1020, _1020, 1.0), 0.0, 1.0);
    float _1044 = fast::clamp(fma(dot(-_1016, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1176 = clamp(dot(_686, half3(_1016)), half(0.0), half(1.0));
    half _1179 = _1176 * _1176;
    half4 _1374 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1179 * _1179, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1191 = _1374.x;
    half3 _1200 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_735).xyz * _725) + min((_725 * ((_963 * _963) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_797) * half(_797)) / fast::max(_783, 9.9999997473787516355514526367188e-05)) * half(_816)) * half(_816)), float3(65504.0))) * clamp(dot(_517, half3(_788)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_725 * ((_1191 * _1191) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1025) * half(_1025)) / fast::max(_1011, 9.9999997473787516355514526367188e-05)) * half(_1044)) * half(_1044)), float3(65504.0))) * clamp(dot(_517, half3(_1016)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1200, half(1.0)));
    return out;
}

