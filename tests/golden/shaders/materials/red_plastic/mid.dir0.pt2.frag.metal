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
    float4 _764 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_569, half3(_585)), half(9.9999997473787516355514526367188e-05)), half(params.facet_perceptualRoughness))), level(0.0));
    float4 _783 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_585), _569)), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _828 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _831 = dot(_828, _828);
    float3 _836 = _828 * rsqrt(fast::max(_831, 9.9999999392252902907785028219223e-09));
    float _840 = _831 * float(frame.punctualLights[0].positionFalloff.w);
    float _845 = fast::clamp(fma(-_840, _840, 1.0), 0.0, 1.0);
    float _864 = fast::clamp(fma(dot(-_836, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _971 = normalize(half3(_585) + half3(_836));
    half _933 = clamp(dot(half3(_836), _971), half(0.0), half(1.0));
    half4 _1023 = half4(cross(_569, _971), half(params.facet_alpha) * clamp(dot(_569, _971), half(0.0), half(1.0))) * half(64.0);
    half _1041 = fma(half(-0.3125), half(params.facet_alpha), half(1.00820004940032958984375));
    half _1042 = (half(12.56637096405029296875) * max(_933 * _933, half(0.1500000059604644775390625))) * _1041;
    half _1047 = half(params.facet_alpha) / ((dot(_1023, _1023) * half(0.000244140625)) * _1042);
    float3 _1094 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1097 = dot(_1094, _1094);
    float3 _1102 = _1094 * rsqrt(fast::max(_1097, 9.9999999392252902907785028219223e-09));
    float _1106 = _1097 * float(frame.punctualLights[1].positionFalloff.w);
    float _1111 = fast::clamp(fma(-_1106, _1106, 1.0), 0.0, 1.0);
    float _1130 = fast::clamp(fma(dot(-_1102, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1237 = normalize(half3(_585) + half3(_1102));
    half _1199 = clamp(dot(half3(_1102), _1237), half(0.0), half(1.0));
    half4 _1289 = half4(cross(_569, _1237), half(params.facet_alpha) * clamp(dot(_569, _1237), half(0.0), half(1.0))) * half(64.0);
    half _1308 = (half(12.56637096405029296875) * max(_1199 * _1199, half(0.1500000059604644775390625))) * _1041;
    half _1313 = half(params.facet_alpha) / ((dot(_1289, _1289) * half(0.000244140625)) * _1308);
    half3 _1324 = (fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_783).xyz * mix(half4(_764).xxx, half4(_764).yyy, half3(float3(params.facet_f0)))) + min((half3(float3(params.facet_f0)) * min((_1047 * _1047) * _1042, half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_845) * half(_845)) / fast::max(_831, 9.9999997473787516355514526367188e-05)) * half(_864)) * half(_864)), float3(65504.0))) * clamp(dot(_569, half3(_836)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((half3(float3(params.facet_f0)) * min((_1313 * _1313) * _1308, half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1111) * half(_1111)) / fast::max(_1097, 9.9999997473787516355514526367188e-05)) * half(_1130)) * half(_1130)), float3(65504.0))) * clamp(dot(_569, half3(_1102)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1324, half(1.0)));
    return out;
}

