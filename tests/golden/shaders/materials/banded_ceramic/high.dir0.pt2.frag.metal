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
    float _805 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    float4 _831 = facet_irradiance.sample(facet_irradianceSmplr, float3(_667), level(0.0));
    half3 _855 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_805))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _922 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _805)), half(0.0), half(1.0));
    half3 _930 = half3((half(0.1599999964237213134765625) * _922) * _922);
    half _939 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _805)), half(0.08900000154972076416015625), half(1.0));
    half _888 = max(dot(_667, half3(_683)), half(9.9999997473787516355514526367188e-05));
    float4 _946 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_888, _939)), level(0.0));
    float4 _965 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_683), _667)), level(_939 * (half(4.0) * (half(2.0) - _939))));
    float3 _1010 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1013 = dot(_1010, _1010);
    float3 _1018 = _1010 * rsqrt(fast::max(_1013, 9.9999999392252902907785028219223e-09));
    float _1022 = _1013 * float(frame.punctualLights[0].positionFalloff.w);
    float _1027 = fast::clamp(fma(-_1022, _1022, 1.0), 0.0, 1.0);
    float _1046 = fast::clamp(fma(dot(-_1018, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1185 = _939 * _939;
    half3 _1196 = normalize(half3(_683) + half3(_1018));
    half _1109 = clamp(dot(_667, half3(_1018)), half(0.0), half(1.0));
    half4 _1265 = half4(cross(_667, _1196), _1185 * clamp(dot(_667, _1196), half(0.0), half(1.0))) * half(64.0);
    half _1239 = half(4096.0) * _1185;
    half _1242 = half(6.283185482025146484375) * max(mix((half(2.0) * _1109) * _888, _1109 + _888, _1185), half(0.000244140625));
    half _1244 = _1239 / (dot(_1265, _1265) * _1242);
    half3 _1137 = _855 * half(0.3183098733425140380859375);
    float3 _1323 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1326 = dot(_1323, _1323);
    float3 _1331 = _1323 * rsqrt(fast::max(_1326, 9.9999999392252902907785028219223e-09));
    float _1335 = _1326 * float(frame.punctualLights[1].positionFalloff.w);
    float _1340 = fast::clamp(fma(-_1335, _1335, 1.0), 0.0, 1.0);
    float _1359 = fast::clamp(fma(dot(-_1331, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1509 = normalize(half3(_683) + half3(_1331));
    half _1422 = clamp(dot(_667, half3(_1331)), half(0.0), half(1.0));
    half4 _1578 = half4(cross(_667, _1509), _1185 * clamp(dot(_667, _1509), half(0.0), half(1.0))) * half(64.0);
    half _1555 = half(6.283185482025146484375) * max(mix((half(2.0) * _1422) * _888, _1422 + _888, _1185), half(0.000244140625));
    half _1557 = _1239 / (dot(_1578, _1578) * _1555);
    half3 _1600 = (fma(_855, half4(_831).xyz, half4(_965).xyz * mix(half4(_946).xxx, half4(_946).yyy, _930)) + min((_1137 + (_930 * min(_1244 * (_1244 * _1242), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1027) * half(_1027)) / fast::max(_1013, 9.9999997473787516355514526367188e-05)) * half(_1046)) * half(_1046)), float3(65504.0))) * _1109), half3(float3(65504.0)))) + min((_1137 + (_930 * min(_1557 * (_1557 * _1555), half(65504.0)))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1340) * half(_1340)) / fast::max(_1326, 9.9999997473787516355514526367188e-05)) * half(_1359)) * half(_1359)), float3(65504.0))) * _1422), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1600, half(1.0)));
    return out;
}

