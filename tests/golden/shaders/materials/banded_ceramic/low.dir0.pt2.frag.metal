#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 glazeColor;
    packed_float3 clayColor;
    float glazeRoughness;
    float clayRoughness;
    float bandsPerUnit;
    float bandSharpness;
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
    half3 _597 = normalize(half3(in.v_normal));
    float3 _613 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _741 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _842 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _741)), half(0.0), half(1.0));
    half _859 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _741)), half(0.08900000154972076416015625), half(1.0));
    half3 _811 = reflect(-half3(_613), _597);
    float4 _866 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_597, half3(_613)), half(9.9999997473787516355514526367188e-05)), _859)), level(0.0));
    half3 _875 = mix(half4(_866).xxx, half4(_866).yyy, half3((half(0.1599999964237213134765625) * _842) * _842));
    float4 _885 = facet_environment.sample(facet_environmentSmplr, float3(_811), level(_859 * (half(4.0) * (half(2.0) - _859))));
    float3 _930 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _933 = dot(_930, _930);
    float3 _938 = _930 * rsqrt(fast::max(_933, 9.9999999392252902907785028219223e-09));
    float _942 = _933 * float(frame.punctualLights[0].positionFalloff.w);
    float _947 = fast::clamp(fma(-_942, _942, 1.0), 0.0, 1.0);
    float _966 = fast::clamp(fma(dot(-_938, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1133 = clamp(dot(_811, half3(_938)), half(0.0), half(1.0));
    half _1136 = _1133 * _1133;
    half4 _1601 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1136 * _1136, _859), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1148 = _1601.x;
    float3 _1193 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1196 = dot(_1193, _1193);
    float3 _1201 = _1193 * rsqrt(fast::max(_1196, 9.9999999392252902907785028219223e-09));
    float _1205 = _1196 * float(frame.punctualLights[1].positionFalloff.w);
    float _1210 = fast::clamp(fma(-_1205, _1205, 1.0), 0.0, 1.0);
    float _1229 = fast::clamp(fma(dot(-_1201, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1396 = clamp(dot(_811, half3(_1201)), half(0.0), half(1.0));
    half _1399 = _1396 * _1396;
    half4 _1626 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1399 * _1399, _859), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1411 = _1626.x;
    half3 _1420 = (fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_741))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_885).xyz * _875) + min((_875 * ((_1148 * _1148) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_947) * half(_947)) / fast::max(_933, 9.9999997473787516355514526367188e-05)) * half(_966)) * half(_966)), float3(65504.0))) * clamp(dot(_597, half3(_938)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_875 * ((_1411 * _1411) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1210) * half(_1210)) / fast::max(_1196, 9.9999997473787516355514526367188e-05)) * half(_1229)) * half(_1229)), float3(65504.0))) * clamp(dot(_597, half3(_1201)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1420, half(1.0)));
    return out;
}

