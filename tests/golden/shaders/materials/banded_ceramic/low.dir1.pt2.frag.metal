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
    float _784 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _893 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _784)), half(0.0), half(1.0));
    half3 _901 = half3((half(0.1599999964237213134765625) * _893) * _893);
    half _910 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _784)), half(0.08900000154972076416015625), half(1.0));
    half3 _856 = reflect(-half3(_632), _616);
    float4 _917 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_616, half3(_632)), half(9.9999997473787516355514526367188e-05)), _910)), level(0.0));
    float4 _943 = facet_environment.sample(facet_environmentSmplr, float3(_856), level(_910 * half(4.0)));
    half3 _871 = mix(half4(_917).xxx, half4(_917).yyy, _901) * (half3(float3(1.0)) + (_901 * ((half(1.0) / half4(_917).y) - half(1.0))));
    half3 _669 = half4(frame.lightDirection).xyz;
    half _1107 = clamp(dot(_856, _669), half(0.0), half(1.0));
    half _1110 = _1107 * _1107;
    half4 _1833 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1110 * _1110, _910), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1122 = _1833.x;
    float3 _1167 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1170 = dot(_1167, _1167);
    float3 _1175 = _1167 * rsqrt(fast::max(_1170, 9.9999999392252902907785028219223e-09));
    float _1179 = _1170 * float(frame.punctualLights[0].positionFalloff.w);
    float _1184 = fast::clamp(fma(-_1179, _1179, 1.0), 0.0, 1.0);
    float _1203 = fast::clamp(fma(dot(-_1175, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1370 = clamp(dot(_856, half3(_1175)), half(0.0), half(1.0));
    half _1373 = _1370 * _1370;
    half4 _1857 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1373 * _1373, _910), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1385 = _1857.x;
    float3 _1430 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1433 = dot(_1430, _1430);
    float3 _1438 = _1430 * rsqrt(fast::max(_1433, 9.9999999392252902907785028219223e-09));
    float _1442 = _1433 * float(frame.punctualLights[1].positionFalloff.w);
    float _1447 = fast::clamp(fma(-_1442, _1442, 1.0), 0.0, 1.0);
    float _1466 = fast::clamp(fma(dot(-_1438, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1633 = clamp(dot(_856, half3(_1438)), half(0.0), half(1.0));
    half _1636 = _1633 * _1633;
    half4 _1882 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1636 * _1636, _910), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1648 = _1882.x;
    half3 _1657 = ((fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_784))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_943).xyz * _871) + min((_871 * ((_1122 * _1122) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_616, _669), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_871 * ((_1385 * _1385) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1184) * half(_1184)) / fast::max(_1170, 9.9999997473787516355514526367188e-05)) * half(_1203)) * half(_1203)), float3(65504.0))) * clamp(dot(_616, half3(_1175)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_871 * ((_1648 * _1648) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1447) * half(_1447)) / fast::max(_1433, 9.9999997473787516355514526367188e-05)) * half(_1466)) * half(_1466)), float3(65504.0))) * clamp(dot(_616, half3(_1438)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1657, half(1.0)));
    return out;
}

