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
    half3 _633 = normalize(half3(in.v_normal));
    float3 _649 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _777 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _885 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _777)), half(0.0), half(1.0));
    half3 _893 = half3((half(0.1599999964237213134765625) * _885) * _885);
    half _902 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _777)), half(0.08900000154972076416015625), half(1.0));
    half _845 = max(dot(_633, half3(_649)), half(9.9999997473787516355514526367188e-05));
    float4 _909 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_845, _902)), level(0.0));
    half3 _928 = half3(float3(1.0)) + (_893 * ((half(1.0) / half4(_909).y) - half(1.0)));
    float4 _935 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_649), _633)), level(_902 * half(4.0)));
    float3 _980 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _983 = dot(_980, _980);
    float3 _988 = _980 * rsqrt(fast::max(_983, 9.9999999392252902907785028219223e-09));
    float _992 = _983 * float(frame.punctualLights[0].positionFalloff.w);
    float _997 = fast::clamp(fma(-_992, _992, 1.0), 0.0, 1.0);
    float _1016 = fast::clamp(fma(dot(-_988, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1150 = _902 * _902;
    half3 _1161 = normalize(half3(_649) + half3(_988));
    half _1077 = clamp(dot(_633, half3(_988)), half(0.0), half(1.0));
    half3 _1188 = cross(_633, _1161);
    half _1191 = clamp(dot(_633, _1161), half(0.0), half(1.0)) * _1150;
    half _1208 = max(mix((half(2.0) * _1077) * _845, _1077 + _845, _1150), half(0.000244140625));
    half _1210 = half(1024.0) * _1150;
    half _1215 = _1210 / (fma(_1191, _1191, dot(_1188, _1188)) * (half(6433.98193359375) * _1208));
    float3 _1263 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1266 = dot(_1263, _1263);
    float3 _1271 = _1263 * rsqrt(fast::max(_1266, 9.9999999392252902907785028219223e-09));
    float _1275 = _1266 * float(frame.punctualLights[1].positionFalloff.w);
    float _1280 = fast::clamp(fma(-_1275, _1275, 1.0), 0.0, 1.0);
    float _1299 = fast::clamp(fma(dot(-_1271, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1444 = normalize(half3(_649) + half3(_1271));
    half _1360 = clamp(dot(_633, half3(_1271)), half(0.0), half(1.0));
    half3 _1471 = cross(_633, _1444);
    half _1474 = clamp(dot(_633, _1444), half(0.0), half(1.0)) * _1150;
    half _1491 = max(mix((half(2.0) * _1360) * _845, _1360 + _845, _1150), half(0.000244140625));
    half _1498 = _1210 / (fma(_1474, _1474, dot(_1471, _1471)) * (half(6433.98193359375) * _1491));
    half3 _1510 = (fma(clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_777))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0), half3(in.v_diffuseLight), half4(_935).xyz * (mix(half4(_909).xxx, half4(_909).yyy, _893) * _928)) + min(((_893 * min(_1215 * (_1215 * (half(6.283185482025146484375) * _1208)), half(65504.0))) * _928) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_997) * half(_997)) / fast::max(_983, 9.9999997473787516355514526367188e-05)) * half(_1016)) * half(_1016)), float3(65504.0))) * _1077), half3(float3(65504.0)))) + min(((_893 * min(_1498 * (_1498 * (half(6.283185482025146484375) * _1491)), half(65504.0))) * _928) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1280) * half(_1280)) / fast::max(_1266, 9.9999997473787516355514526367188e-05)) * half(_1299)) * half(_1299)), float3(65504.0))) * _1360), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1510, half(1.0)));
    return out;
}

