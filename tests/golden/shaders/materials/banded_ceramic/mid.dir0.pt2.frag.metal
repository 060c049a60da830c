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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _698 = normalize(half3(in.v_normal));
    float3 _714 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _839 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _939 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _839)), half(0.0), half(1.0));
    half3 _947 = half3((half(0.1599999964237213134765625) * _939) * _939);
    half _956 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _839)), half(0.08900000154972076416015625), half(1.0));
    float4 _963 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(max(dot(_698, half3(_714)), half(9.9999997473787516355514526367188e-05)), _956)), level(0.0));
    float4 _982 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_714), _698)), level(_956 * (half(4.0) * (half(2.0) - _956))));
    float3 _1027 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1030 = dot(_1027, _1027);
    float3 _1035 = _1027 * rsqrt(fast::max(_1030, 9.9999999392252902907785028219223e-09));
    float _1039 = _1030 * float(frame.punctualLights[0].positionFalloff.w);
    float _1044 = fast::clamp(fma(-_1039, _1039, 1.0), 0.0, 1.0);
    float _1063 = fast::clamp(fma(dot(-_1035, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1217 = _956 * _956;
    half3 _1127 = half3(_714) + half3(_1035);
    half3 _1137 = _1127 * (half(64.0) * rsqrt(dot(_1127, _1127)));
    half _1146 = clamp(dot(half3(_1035), _1137) * half(0.015625), half(0.0), half(1.0));
    half4 _1374 = half4(cross(_698, _1137), _1217 * clamp(dot(_698, _1137), half(0.0), half(64.0)));
    half _1394 = fma(half(-0.3125), _1217, half(1.00820004940032958984375));
    half _1395 = (half(12.56637096405029296875) * max(_1146 * _1146, half(0.1500000059604644775390625))) * _1394;
    half _1407 = _1217 / ((dot(_1374, _1374) * half(0.000244140625)) * _1395);
    float3 _1454 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1457 = dot(_1454, _1454);
    float3 _1462 = _1454 * rsqrt(fast::max(_1457, 9.9999999392252902907785028219223e-09));
    float _1466 = _1457 * float(frame.punctualLights[1].positionFalloff.w);
    float _1471 = fast::clamp(fma(-_1466, _1466, 1.0), 0.0, 1.0);
    float _1490 = fast::clamp(fma(dot(-_1462, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1554 = half3(_714) + half3(_1462);
    half3 _1564 = _1554 * (half(64.0) * rsqrt(dot(_1554, _1554)));
    half _1573 = clamp(dot(half3(_1462), _1564) * half(0.015625), half(0.0), half(1.0));
    half4 _1801 = half4(cross(_698, _1564), _1217 * clamp(dot(_698, _1564), half(0.0), half(64.0)));
    half _1822 = (half(12.56637096405029296875) * max(_1573 * _1573, half(0.1500000059604644775390625))) * _1394;
    half _1834 = _1217 / ((dot(_1801, _1801) * half(0.000244140625)) * _1822);
    half3 _1845 = (fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_839))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_982).xyz * mix(half4(_963).xxx, half4(_963).yyy, _947)) + min((_947 * half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1044) * half(_1044)) / fast::max(_1030, 9.9999997473787516355514526367188e-05)) * half(_1063)) * half(_1063)), float3(65504.0)))) * (min((_1407 * _1407) * _1395, half(65504.0)) * clamp(dot(_698, half3(_1035)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min((_947 * half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1471) * half(_1471)) / fast::max(_1457, 9.9999997473787516355514526367188e-05)) * half(_1490)) * half(_1490)), float3(65504.0)))) * (min((_1834 * _1834) * _1822, half(65504.0)) * clamp(dot(_698, half3(_1462)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1845, half(1.0)));
    return out;
}

