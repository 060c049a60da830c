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
    half3 _707 = reflect(-half3(_533), _517);
    float4 _737 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_517, half3(_533)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    half3 _746 = mix(half4(_737).xxx, half4(_737).yyy, half3(float3(params.facet_f0)));
    float4 _756 = facet_environment.sample(facet_environmentSmplr, float3(_707), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _570 = half4(frame.lightDirection).xyz;
    half _885 = clamp(dot(_707, _570), half(0.0), half(1.0));
    half _888 = _885 * _885;
    half4 _1502 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_888 * _888, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _900 = _1502.x;
    float3 _945 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _948 = dot(_945, _945);
    float3 _953 = _945 * rsqrt(fast::max(_948, 9.9999999392252902907785028219223e-09));
    float _957 = _948 * float(frame.punctualLights[0].positionFalloff.w);
    float _962 = fast::clamp(fma(-_957, _957, 1.0), 0.0, 1.0);
    float _981 = fast::clamp(fma(dot(-_953, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1113 = clamp(dot(_707, half3(_953)), half(0.0), half(1.0));
    half _1116 = _1113 * _1113;
    half4 _1527 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1116 * _1116, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1128 = _1527.x;
    float3 _1173 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1176 = dot(_1173, _1173);
    float3 _1181 = _1173 * rsqrt(fast::max(_1176, 9.9999999392252902907785028219223e-09));
    float _1185 = _1176 * float(frame.punctualLights[1].positionFalloff.w);
    float _1190 = fast::clamp(fma(-_1185, _1185, 1.0), 0.0, 1.0);
    float _1209 = fast::clamp(fma(dot(-_1181, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1341 = clamp(dot(_707, half3(_1181)), half(0.0), half(1.0));
    half _1344 = _1341 * _1341;
    half4 _1553 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1344 * _1344, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1356 = _1553.x;
    half3 _1365 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_756).xyz * _746) + min((_746 * ((_900 * _900) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_517, _570), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_746 * ((_1128 * _1128) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_962) * half(_962)) / fast::max(_948, 9.9999997473787516355514526367188e-05)) * half(_981)) * half(_981)), float3(65504.0))) * clamp(dot(_517, half3(_953)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_746 * ((_1356 * _1356) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1190) * half(_1190)) / fast::max(_1176, 9.9999997473787516355514526367188e-05)) * half(_1209)) * half(_1209)), float3(65504.0))) * clamp(dot(_517, half3(_1181)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1365, half(1.0)));
    return out;
}

