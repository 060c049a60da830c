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
    half3 _703 = reflect(-half3(_529), _513);
    float4 _733 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_513, half3(_529)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    half3 _742 = mix(half4(_733).xxx, half4(_733).yyy, half3(float3(params.facet_f0)));
    float4 _749 = facet_environment.sample(facet_environmentSmplr, float3(_703), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _566 = half4(frame.lightDirection).xyz;
    half _878 = clamp(dot(_703, _566), half(0.0), half(1.0));
    half _881 = _878 * _878;
    half4 _1493 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_881 * _881, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _893 = _1493.x;
    float3 _938 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _941 = dot(_938, _938);
    float3 _946 = _938 * rsqrt(fast::max(_941, 9.9999999392252902907785028219223e-09));
    float _950 = _941 * float(frame.punctualLights[0].positionFalloff.w);
    float _955 = fast::clamp(fma(-_950, _950, 1.0), 0.0, 1.0);
    float _974 = fast::clamp(fma(dot(-_946, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1106 = clamp(dot(_703, half3(_946)), half(0.0), half(1.0));
    half _1109 = _1106 * _1106;
    half4 _1518 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1109 * _1109, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1121 = _1518.x;
    float3 _1166 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1169 = dot(_1166, _1166);
    float3 _1174 = _1166 * rsqrt(fast::max(_1169, 9.9999999392252902907785028219223e-09));
    float _1178 = _1169 * float(frame.punctualLights[1].positionFalloff.w);
    float _1183 = fast::clamp(fma(-_1178, _1178, 1.0), 0.0, 1.0);
    float _1202 = fast::clamp(fma(dot(-_1174, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1334 = clamp(dot(_703, half3(_1174)), half(0.0), half(1.0));
    half _1337 = _1334 * _1334;
    half4 _1544 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1337 * _1337, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1349 = _1544.x;
    half3 _1358 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_749).xyz * _742) + min((_742 * ((_893 * _893) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_513, _566), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_742 * ((_1121 * _1121) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_955) * half(_955)) / fast::max(_941, 9.9999997473787516355514526367188e-05)) * half(_974)) * half(_974)), float3(65504.0))) * clamp(dot(_513, half3(_946)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_742 * ((_1349 * _1349) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1183) * half(_1183)) / fast::max(_1169, 9.9999997473787516355514526367188e-05)) * half(_1202)) * half(_1202)), float3(65504.0))) * clamp(dot(_513, half3(_1174)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1358, half(1.0)));
    return out;
}

