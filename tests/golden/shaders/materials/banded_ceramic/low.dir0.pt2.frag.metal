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
    half3 _616 = normalize(half3(in.v_normal));
    float3 _632 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _763 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _872 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _763)), half(0.0), half(1.0));
    half3 _880 = half3((half(0.1599999964237213134765625) * _872) * _872);
    half _889 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _763)), half(0.08900000154972076416015625), half(1.0));
    half3 _835 = reflect(-half3(_632), _616);
    float4 _896 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_616, half3(_632)), half(9.9999997473787516355514526367188e-05)), _889)), level(0.0));
    float4 _922 = facet_environment.sample(facet_environmentSmplr, float3(_835), level(_889 * half(4.0)));
    half3 _850 = mix(half4(_896).xxx, half4(_896).yyy, _880) * (half3(float3(1.0)) + (_880 * ((half(1.0) / half4(_896).y) - half(1.0))));
    float3 _967 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _970 = dot(_967, _967);
    float3 _975 = _967 * rsqrt(fast::max(_970, 9.9999999392252902907785028219223e-09));
    float _979 = _970 * float(frame.punctualLights[0].positionFalloff.w);
    float _984 = fast::clamp(fma(-_979, _979, 1.0), 0.0, 1.0);
    float _1003 = fast::clamp(fma(dot(-_975, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1170 = clamp(dot(_835, half3(_975)), half(0.0), half(1.0));
    half _1173 = _1170 * _1170;
    half4 _1642 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1173 * _1173, _889), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1185 = _1642.x;
    float3 _1230 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1233 = dot(_1230, _1230);
    float3 _1238 = _1230 * rsqrt(fast::max(_1233, 9.9999999392252902907785028219223e-09));
    float _1242 = _1233 * float(frame.punctualLights[1].positionFalloff.w);
    float _1247 = fast::clamp(fma(-_1242, _1242, 1.0), 0.0, 1.0);
    float _1266 = fast::clamp(fma(dot(-_1238, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1433 = clamp(dot(_835, half3(_1238)), half(0.0), half(1.0));
    half _1436 = _1433 * _1433;
    half4 _1667 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1436 * _1436, _889), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1448 = _1667.x;
    half3 _1457 = (fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_763))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_922).xyz * _850) + min((_850 * ((_1185 * _1185) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_984) * half(_984)) / fast::max(_970, 9.9999997473787516355514526367188e-05)) * half(_1003)) * half(_1003)), float3(65504.0))) * clamp(dot(_616, half3(_975)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_850 * ((_1448 * _1448) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1247) * half(_1247)) / fast::max(_1233, 9.9999997473787516355514526367188e-05)) * half(_1266)) * half(_1266)), float3(65504.0))) * clamp(dot(_616, half3(_1238)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1457, half(1.0)));
    return out;
}

