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
    half3 _536 = normalize(half3(in.v_normal));
    float3 _552 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _707 = reflect(-half3(_552), _536);
    float4 _743 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_536, half3(_552)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _769 = facet_environment.sample(facet_environmentSmplr, float3(_707), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _722 = mix(half4(_743).xxx, half4(_743).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_743).y) - half(1.0))));
    float3 _814 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _817 = dot(_814, _814);
    float3 _822 = _814 * rsqrt(fast::max(_817, 9.9999999392252902907785028219223e-09));
    float _826 = _817 * float(frame.punctualLights[0].positionFalloff.w);
    float _831 = fast::clamp(fma(-_826, _826, 1.0), 0.0, 1.0);
    float _850 = fast::clamp(fma(dot(-_822, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _982 = clamp(dot(_707, half3(_822)), half(0.0), half(1.0));
    half _985 = _982 * _982;
    half4 _1386 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_985 * _985, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _997 = _1386.x;
    float3 _1042 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1045 = dot(_1042, _1042);
    float3 _1050 = _1042 * rsqrt(fast::max(_1045, 9.9999999392252902907785028219223e-09));
    float _1054 = _1045 * float(frame.punctualLights[1].positionFalloff.w);
    float _1059 = fast::clamp(fma(-_1054, _1054, 1.0), 0.0, 1.0);
    float _1078 = fast::clamp(fma(dot(-_1050, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1210 = clamp(dot(_707, half3(_1050)), half(0.0), half(1.0));
    half _1213 = _1210 * _1210;
    half4 _1412 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1213 * _1213, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1225 = _1412.x;
    half3 _1234 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_769).xyz * _722) + min((_722 * ((_997 * _997) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_831) * half(_831)) / fast::max(_817, 9.9999997473787516355514526367188e-05)) * half(_850)) * half(_850)), float3(65504.0))) * clamp(dot(_536, half3(_822)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_722 * ((_1225 * _1225) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1059) * half(_1059)) / fast::max(_1045, 9.9999997473787516355514526367188e-05)) * half(_1078)) * half(_1078)), float3(65504.0))) * clamp(dot(_536, half3(_1050)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1234, half(1.0)));
    return out;
}

