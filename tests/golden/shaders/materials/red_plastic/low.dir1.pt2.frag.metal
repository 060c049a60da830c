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
    half3 _732 = reflect(-half3(_556), _540);
    float4 _768 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_540, half3(_556)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _797 = facet_environment.sample(facet_environmentSmplr, float3(_732), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _747 = mix(half4(_768).xxx, half4(_768).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_768).y) - half(1.0))));
    half3 _593 = half4(frame.lightDirection).xyz;
    half _926 = clamp(dot(_732, _593), half(0.0), half(1.0));
    half _929 = _926 * _926;
    half4 _1549 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_929 * _929, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _941 = _1549.x;
    float3 _986 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _989 = dot(_986, _986);
    float3 _994 = _986 * rsqrt(fast::max(_989, 9.9999999392252902907785028219223e-09));
    float _998 = _989 * float(frame.punctualLights[0].positionFalloff.w);
    float _1003 = fast::clamp(fma(-_998, _998, 1.0), 0.0, 1.0);
    float _1022 = fast::clamp(fma(dot(-_994, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1154 = clamp(dot(_732, half3(_994)), half(0.0), half(1.0));
    half _1157 = _1154 * _1154;
    half4 _1574 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1157 * _1157, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1169 = _1574.x;
    float3 _1214 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1217 = dot(_1214, _1214);
    float3 _1222 = _1214 * rsqrt(fast::max(_1217, 9.9999999392252902907785028219223e-09));
    float _1226 = _1217 * float(frame.punctualLights[1].positionFalloff.w);
    float _1231 = fast::clamp(fma(-_1226, _1226, 1.0), 0.0, 1.0);
    float _1250 = fast::clamp(fma(dot(-_1222, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1382 = clamp(dot(_732, half3(_1222)), half(0.0), half(1.0));
    half _1385 = _1382 * _1382;
    half4 _1600 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1385 * _1385, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1397 = _1600.x;
    half3 _1406 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_797).xyz * _747) + min((_747 * ((_941 * _941) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_540, _593), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_747 * ((_1169 * _1169) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1003) * half(_1003)) / fast::max(_989, 9.9999997473787516355514526367188e-05)) * half(_1022)) * half(_1022)), float3(65504.0))) * clamp(dot(_540, half3(_994)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_747 * ((_1397 * _1397) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1231) * half(_1231)) / fast::max(_1217, 9.9999997473787516355514526367188e-05)) * half(_1250)) * half(_1250)), float3(65504.0))) * clamp(dot(_540, half3(_1222)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1406, half(1.0)));
    return out;
}

