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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _569 = normalize(half3(in.v_normal));
    float3 _585 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float4 _785 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_569, half3(_585)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _804 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_585), _569)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _622 = half4(frame.lightDirection).xyz;
    half3 _908 = normalize(half3(_585) + _622);
    half _870 = clamp(dot(_622, _908), half(0.0), half(1.0));
    half4 _960 = half4(cross(_569, _908), half(params.facet_alpha) * clamp(dot(_569, _908), half(0.0), half(1.0))) * half(64.0);
    half _978 = fma(half(-0.3125), half(params.facet_alpha), half(1.00820004940032958984375));
    half _979 = (half(12.56637096405029296875) * max(_870 * _870, half(0.1500000059604644775390625))) * _978;
    half _984 = half(params.facet_alpha) / ((dot(_960, _960) * half(0.000244140625)) * _979);
    float3 _1031 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1034 = dot(_1031, _1031);
    float3 _1039 = _1031 * rsqrt(fast::max(_1034, 9.9999999392252902907785028219223e-09));
    float _1043 = _1034 * float(frame.punctualLights[0].positionFalloff.w);
    float _1048 = fast::clamp(fma(-_1043, _1043, 1.0), 0.0, 1.0);
    float _1067 = fast::clamp(fma(dot(-_1039, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1174 = normalize(half3(_585) + half3(_1039));
    half _1136 = clamp(dot(half3(_1039), _1174), half(0.0), half(1.0));
    half4 _1226 = half4(cross(_569, _1174), half(params.facet_alpha) * clamp(dot(_569, _1174), half(0.0), half(1.0))) * half(64.0);
    half _1245 = (half(12.56637096405029296875) * max(_1136 * _1136, half(0.1500000059604644775390625))) * _978;
    half _1250 = half(params.facet_alpha) / ((dot(_1226, _1226) * half(0.000244140625)) * _1245);
    float3 _1297 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1300 = dot(_1297, _1297);
    float3 _1305 = _1297 * rsqrt(fast::max(_1300, 9.9999999392252902907785028219223e-09));
    float _1309 = _1300 * float(frame.punctualLights[1].positionFalloff.w);
    float _1314 = fast::clamp(fma(-_1309, _1309, 1.0), 0.0, 1.0);
    float _1333 = fast::clamp(fma(dot(-_1305, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1440 = normalize(half3(_585) + half3(_1305));
    half _1402 = clamp(dot(half3(_1305), _1440), half(0.0), half(1.0));
    half4 _1492 = half4(cross(_569, _1440), half(params.facet_alpha) * clamp(dot(_569, _1440), half(0.0), half(1.0))) * half(64.0);
    half _1511 = (half(12.56637096405029296875) * max(_1402 * _1402, half(0.1500000059604644775390625))) * _978;
    half _1516 = half(params.facet_alpha) / ((dot(_1492, _1492) * half(0.000244140625)) * _1511);
    half3 _1527 = ((fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_804).xyz * mix(half4(_785).xxx, half4(_785).yyy, half3(float3(params.facet_f0)))) + min((half3(float3(params.facet_f0)) * min((_984 * _984) * _979, half(65504.0))) * (half4(frame.lightColor).xyz * clamp(dot(_569, _622), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((half3(float3(params.facet_f0)) * min((_1250 * _1250) * _1245, half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1048) * half(_1048)) / fast::max(_1034, 9.9999997473787516355514526367188e-05)) * half(_1067)) * half(_1067)), float3(65504.0))) * clamp(dot(_569, half3(_1039)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((half3(float3(params.facet_f0)) * min((_1516 * _1516) * _1511, half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1314) * half(_1314)) / fast::max(_1300, 9.9999997473787516355514526367188e-05)) * half(_1333)) * half(_1333)), float3(65504.0))) * clamp(dot(_569, half3(_1305)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1527, half(1.0)));
    return out;
}

