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
    float _781 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _890 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _781)), half(0.0), half(1.0));
    half3 _898 = half3((half(0.1599999964237213134765625) * _890) * _890);
    half _907 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _781)), half(0.08900000154972076416015625), half(1.0));
    half3 _853 = reflect(-half3(_632), _616);
    float4 _914 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_616, half3(_632)), half(9.9999997473787516355514526367188e-05)), _907)), level(0.0));
    float4 _940 = facet_environment.sample(facet_environmentSmplr, float3(_853), level(_907 * half(4.0)));
    half3 _868 = mix(half4(_914).xxx, half4(_914).yyy, _898) * (half3(float3(1.0)) + (_898 * ((half(1.0) / half4(_914).y) - half(1.0))));
    half3 _669 = half4(frame.lightDirection).xyz;
    half _1104 = clamp(dot(_853, _669), half(0.0), half(1.0));
    half _1107 = _1104 * _1104;
    half4 _1830 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1107 * _1107, _907), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1119 = _1830.x;
    float3 _1164 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1167 = dot(_1164, _1164);
    float3 _1172 = _1164 * rsqrt(fast::max(_1167, 9.9999999392252902907785028219223e-09));
    float _1176 = _1167 * float(frame.punctualLights[0].positionFalloff.w);
    float _1181 = fast::clamp(fma(-_1176, _1176, 1.0), 0.0, 1.0);
    float _1200 = fast::clamp(fma(dot(-_1172, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1367 = clamp(dot(_853, half3(_1172)), half(0.0), half(1.0));
    half _1370 = _1367 * _1367;
    half4 _1854 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1370 * _1370, _907), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1382 = _1854.x;
    float3 _1427 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1430 = dot(_1427, _1427);
    float3 _1435 = _1427 * rsqrt(fast::max(_1430, 9.9999999392252902907785028219223e-09));
    float _1439 = _1430 * float(frame.punctualLights[1].positionFalloff.w);
    float _1444 = fast::clamp(fma(-_1439, _1439, 1.0), 0.0, 1.0);
    float _1463 = fast::clamp(fma(dot(-_1435, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half _1630 = clamp(dot(_853, half3(_1435)), half(0.0), half(1.0));
    half _1633 = _1630 * _1630;
    half4 _1879 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1633 * _1633, _907), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1645 = _1879.x;
    half3 _1654 = ((fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_781))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_940).xyz * _868) + min((_868 * ((_1119 * _1119) * half(5.092957973480224609375))) * (half4(frame.lightColor).xyz * clamp(dot(_616, _669), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_868 * ((_1382 * _1382) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1181) * half(_1181)) / fast::max(_1167, 9.9999997473787516355514526367188e-05)) * half(_1200)) * half(_1200)), float3(65504.0))) * clamp(dot(_616, half3(_1172)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_868 * ((_1645 * _1645) * half(5.092957973480224609375))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1444) * half(_1444)) / fast::max(_1430, 9.9999997473787516355514526367188e-05)) * half(_1463)) * half(_1463)), float3(65504.0))) * clamp(dot(_616, half3(_1435)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1654, half(1.0)));
    return out;
}

