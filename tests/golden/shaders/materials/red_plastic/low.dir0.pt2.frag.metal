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
    half3 _540 = normalize(half3(in.v_normal));
    float3 _556 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _711 = reflect(-half3(_556), _540);
    float4 _747 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_540, half3(_556)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _776 = facet_environment.sample(facet_environmentSmplr, float3(_711), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _726 = mix(half4(_747).xxx, half4(_747).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_747).y) - half(1.0))));
    float3 _821 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _824 = dot(_821, _821);
    float3 _829 = _821 * rsqrt(fast::max(_824, 9.9999999392252902907785028219223e-09));
    float _833 = _824 * float(frame.punctualLights[0].positionFalloff.w);
    float _838 = fast::clamp(fma(-_833, _833, 1.0), 0.0, 1.0);
    float _857 = fast::clamp(fma(dot(-_829, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _989 = clamp(dot(_711, half3(_829)), half(0.0), half(1.0));
    half _992 = _989 * _989;
    half4 _1395 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_992 * _992, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1004 = _1395.x;
    float3 _1049 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1052 = dot(_1049, _1049);
    float3 _1057 = _1049 * rsqrt(fast::max(_1052, 9.9999999392252902907785028219223e-09));
    float _1061 = _1052 * float(frame.punctualLights[1].positionFalloff.w);
    float _1066 = fast::clamp(fma(-_1061, _1061, 1.0), 0.0, 1.0);
    float _1085 = fast::clamp(fma(dot(-_1057, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1217 = clamp(dot(_711, half3(_1057)), half(0.0), half(1.0));
    half _1220 = _1217 * _1217;
    half4 _1421 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1220 * _1220, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1232 = _1421.x;
    half3 _1241 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_776).xyz * _726) + min((_726 * ((_1004 * _1004) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_838) * half(_838)) / fast::max(_824, 9.9999997473787516355514526367188e-05)) * half(_857)) * half(_857)), float3(65504.0))) * clamp(dot(_540, half3(_829)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_726 * ((_1232 * _1232) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1066) * half(_1066)) / fast::max(_1052, 9.9999997473787516355514526367188e-05)) * half(_1085)) * half(_1085)), float3(65504.0))) * clamp(dot(_540, half3(_1057)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1241, half(1.0)));
    return out;
}

