#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 base;
    float roughness;
    packed_float3 sheen;
    float sheenRoughness;
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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _744 = normalize(half3(in.v_normal));
    float3 _760 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _923 = max(dot(_744, half3(_760)), half(9.9999997473787516355514526367188e-05));
    half3 _927 = reflect(-half3(_760), _744);
    float4 _963 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_923, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _994 = facet_environment.sample(facet_environmentSmplr, float3(_927), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _942 = mix(half4(_963).xxx, half4(_963).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_963).y) - half(1.0))));
    half _1071 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1028 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_923, _1071)), level(0.0));
    half3 _1078 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1870 = half4(_1028);
    half _1041 = _1870.z;
    half _1043 = fma(half(-float(max(_1078.x, max(_1078.y, _1078.z)))), _1041, half(1.0));
    half _1087 = _1071 * _1071;
    half4 _1874 = half4(_1028);
    half _1048 = _1874.w;
    float4 _1104 = facet_environment.sample(facet_environmentSmplr, float3(_927), level(_1071 * (half(4.0) * (half(2.0) - _1071))));
    float3 _1141 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1144 = dot(_1141, _1141);
    float3 _1149 = _1141 * rsqrt(fast::max(_1144, 9.9999999392252902907785028219223e-09));
    float _1153 = _1144 * float(frame.punctualLights[0].positionFalloff.w);
    float _1158 = fast::clamp(fma(-_1153, _1153, 1.0), 0.0, 1.0);
    float _1177 = fast::clamp(fma(dot(-_1149, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1188 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1158) * half(_1158)) / fast::max(_1144, 9.9999997473787516355514526367188e-05)) * half(_1177)) * half(_1177)), float3(65504.0));
    half _1243 = clamp(dot(_744, half3(_1149)), half(0.0), half(1.0));
    half _1247 = clamp(dot(_744, normalize(half3(_760) + half3(_1149))), half(0.0), half(1.0));
    half _1326 = clamp(dot(_927, half3(_1149)), half(0.0), half(1.0));
    half _1329 = _1326 * _1326;
    half4 _1905 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1329 * _1329, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1341 = _1905.x;
    half _1375 = half(8192.0) * fma(half(-float(_1243)), _923, _1243 + _923);
    half _1379 = half(1.0) / (_1087 * _1375);
    half _1386 = half(2048.0) * _1087;
    float3 _1444 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1447 = dot(_1444, _1444);
    float3 _1452 = _1444 * rsqrt(fast::max(_1447, 9.9999999392252902907785028219223e-09));
    float _1456 = _1447 * float(frame.punctualLights[1].positionFalloff.w);
    float _1461 = fast::clamp(fma(-_1456, _1456, 1.0), 0.0, 1.0);
    float _1480 = fast::clamp(fma(dot(-_1452, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1491 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1461) * half(_1461)) / fast::max(_1447, 9.9999997473787516355514526367188e-05)) * half(_1480)) * half(_1480)), float3(65504.0));
    half _1546 = clamp(dot(_744, half3(_1452)), half(0.0), half(1.0));
    half _1550 = clamp(dot(_744, normalize(half3(_760) + half3(_1452))), half(0.0), half(1.0));
    half _1629 = clamp(dot(_927, half3(_1452)), half(0.0), half(1.0));
    half _1632 = _1629 * _1629;
    half4 _1948 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1632 * _1632, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1644 = _1948.x;
    half _1678 = half(8192.0) * fma(half(-float(_1546)), _923, _1546 + _923);
    half _1682 = half(1.0) / (_1087 * _1678);
    half3 _1711 = (fma(half4(_1104).xyz, _1078 * _1041, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_994).xyz * _942) * _1043) + min(fma(_942 * ((_1341 * _1341) * half(5.092957973480224609375)), (half3(_1188) * _1243) * _1043, (_1078 * ((((fma(_1379, _1375, half(2.0)) * pow(max(fma(half(-float(_1247)), _1247, half(1.0)), half(0.0)), half(0.5) * (_1379 * _1375))) * half(0.15915493667125701904296875)) * (_1243 * (_1379 * _1386))) * _1048)) * half3(_1188)), half3(float3(65504.0)))) + min(fma(_942 * ((_1644 * _1644) * half(5.092957973480224609375)), (half3(_1491) * _1546) * _1043, (_1078 * ((((fma(_1682, _1678, half(2.0)) * pow(max(fma(half(-float(_1550)), _1550, half(1.0)), half(0.0)), half(0.5) * (_1682 * _1678))) * half(0.15915493667125701904296875)) * (_1546 * (_1682 * _1386))) * _1048)) * half3(_1491)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1711, half(1.0)));
    return out;
}

