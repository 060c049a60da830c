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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], texturecube<float> facet_irradiance [[texture(4)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]], sampler facet_irradianceSmplr [[sampler(4)]])
{
    main0_out out = {};
    half3 _667 = normalize(half3(in.v_normal));
    float3 _683 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _826 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float4 _852 = facet_irradiance.sample(facet_irradianceSmplr, float3(_667), level(0.0));
    half3 _876 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_826))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _943 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _826)), half(0.0), half(1.0));
    half3 _951 = half3((half(0.1599999964237213134765625) * _943) * _943);
    half _960 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _826)), half(0.08900000154972076416015625), half(1.0));
    half _909 = max(dot(_667, half3(_683)), half(9.9999997473787516355514526367188e-05));
    float4 _967 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_909, _960)), level(0.0));
    float4 _986 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_683), _667)), level(_960 * (half(4.0) * (half(2.0) - _960))));
    half3 _717 = half4(frame.lightDirection).xyz;
    half _1122 = _960 * _960;
    half3 _1133 = normalize(half3(_683) + _717);
    half _1046 = clamp(dot(_667, _717), half(0.0), half(1.0));
    half4 _1202 = half4(cross(_667, _1133), _1122 * clamp(dot(_667, _1133), half(0.0), half(1.0))) * half(64.0);
    half _1176 = half(4096.0) * _1122;
    half _1179 = half(6.283185482025146484375) * max(mix((half(2.0) * _1046) * _909, _1046 + _909, _1122), half(0.000244140625));
    half _1181 = _1176 / (dot(_1202, _1202) * _1179);
    half3 _1074 = _876 * half(0.3183098733425140380859375);
    float3 _1260 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1263 = dot(_1260, _1260);
    float3 _1268 = _1260 * rsqrt(fast::max(_1263, 9.9999999392252902907785028219223e-09));
    float _1272 = _1263 * float(frame.punctualLights[0].positionFalloff.w);
    float _1277 = fast::clamp(fma(-_1272, _1272, 1.0), 0.0, 1.0);
    float _1296 = fast::clamp(fma(dot(-_1268, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1446 = normalize(half3(_683) + half3(_1268));
    half _1359 = clamp(dot(_667, half3(_1268)), half(0.0), half(1.0));
    half4 _1515 = half4(cross(_667, _1446), _1122 * clamp(dot(_667, _1446), half(0.0), half(1.0))) * half(64.0);
    half _1492 = half(6.283185482025146484375) * max(mix((half(2.0) * _1359) * _909, _1359 + _909, _1122), half(0.000244140625));
    half _1494 = _1176 / (dot(_1515, _1515) * _1492);
    float3 _1573 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1576 = dot(_1573, _1573);
    float3 _1581 = _1573 * rsqrt(fast::max(_1576, 9.9999999392252902907785028219223e-09));
    float _1585 = _1576 * float(frame.punctualLights[1].positionFalloff.w);
    float _1590 = fast::clamp(fma(-_1585, _1585, 1.0), 0.0, 1.0);
    float _1609 = fast::clamp(fma(dot(-_1581, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1759 = normalize(half3(_683) + half3(_1581));
    half _1672 = clamp(dot(_667, half3(_1581)), half(0.0), half(1.0));
    half4 _1828 = half4(cross(_667, _1759), _1122 * clamp(dot(_667, _1759), half(0.0), half(1.0))) * half(64.0);
    half _1805 = half(6.283185482025146484375) * max(mix((half(2.0) * _1672) * _909, _1672 + _909, _1122), half(0.000244140625));
    half _1807 = _1176 / (dot(_1828, _1828) * _1805);
    half3 _1850 = ((fma(_876, half4(_852).xyz, half4(_986).xyz * mix(half4(_967).xxx, half4(_967).yyy, _951)) + min((_1074 + (_951 * min(_1181 * (_1181 * _1179), half(65504.0)))) * (half4(frame.lightColor).xyz * _1046), half3(float3(65504.0)))) + min((_1074 + (_951 * min(_1494 * (_1494 * _1492), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1277) * half(_1277)) / fast::max(_1263, 9.9999997473787516355514526367188e-05)) * half(_1296)) * half(_1296)), float3(65504.0))) * _1359), half3(float3(65504.0)))) + min((_1074 + (_951 * min(_1807 * (_1807 * _1805), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1590) * half(_1590)) / fast::max(_1576, 9.9999997473787516355514526367188e-05)) * half(_1609)) * half(_1609)), float3(65504.0))) * _1672), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1850, half(1.0)));
    return out;
}

