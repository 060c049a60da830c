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
    half3 _710 = reflect(-half3(_552), _536);
    float4 _746 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_536, half3(_552)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _772 = facet_environment.sample(facet_environmentSmplr, float3(_710), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _725 = mix(half4(_746).xxx, half4(_746).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_746).y) - half(1.0))));
    float3 _817 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _820 = dot(_817, _817);
    float3 _825 = _817 * rsqrt(fast::max(_820, 9.9999999392252902907785028219223e-09));
    float _829 = _820 * float(frame.punctualLights[0].positionFalloff.w);
    float _834 = fast::clamp(fma(-_829, _829, 1.0), 0.0, 1.0);
    float _853 = fast::clamp(fma(dot(-_825, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _985 = clamp(dot(_710, half3(_825)), half(0.0), half(1.0));
    half _988 = _985 * _985;
    half4 _1389 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_988 * _988, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1000 = _1389.x;
    float3 _1045 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1048 = dot(_1045, _1045);
    float3 _1053 = _1045 * rsqrt(fast::max(_1048, 9.9999999392252902907785028219223e-09));
    float _1057 = _1048 * float(frame.punctualLights[1].positionFalloff.w);
    float _1062 = fast::clamp(fma(-_1057, _1057, 1.0), 0.0, 1.0);
    float _1081 = fast::clamp(fma(dot(-_1053, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1213 = clamp(dot(_710, half3(_1053)), half(0.0), half(1.0));
    half _1216 = _1213 * _1213;
    half4 _1415 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1216 * _1216, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1228 = _1415.x;
    half3 _1237 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_772).xyz * _725) + min((_725 * ((_1000 * _1000) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_834) * half(_834)) / fast::max(_820, 9.9999997473787516355514526367188e-05)) * half(_853)) * half(_853)), float3(65504.0))) * clamp(dot(_536, half3(_825)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_725 * ((_1228 * _1228) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1062) * half(_1062)) / fast::max(_1048, 9.9999997473787516355514526367188e-05)) * half(_1081)) * half(_1081)), float3(65504.0))) * clamp(dot(_536, half3(_1053)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1237, half(1.0)));
    return out;
}

