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
    half3 _719 = normalize(half3(in.v_normal));
    float3 _735 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _896 = max(dot(_719, half3(_735)), half(9.9999997473787516355514526367188e-05));
    half3 _900 = reflect(-half3(_735), _719);
    float4 _930 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_896, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _939 = mix(half4(_930).xxx, half4(_930).yyy, half3(float3(params.facet_f0)));
    float4 _949 = facet_environment.sample(facet_environmentSmplr, float3(_900), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1026 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _983 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_896, _1026)), level(0.0));
    half3 _1033 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1817 = half4(_983);
    half _996 = _1817.z;
    half _998 = fma(half(-float(max(_1033.x, max(_1033.y, _1033.z)))), _996, half(1.0));
    half _1042 = _1026 * _1026;
    half4 _1821 = half4(_983);
    half _1003 = _1821.w;
    float4 _1057 = facet_environment.sample(facet_environmentSmplr, float3(_900), level(_1026 * (half(4.0) * (half(2.0) - _1026))));
    float3 _1094 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1097 = dot(_1094, _1094);
    float3 _1102 = _1094 * rsqrt(fast::max(_1097, 9.9999999392252902907785028219223e-09));
    float _1106 = _1097 * float(frame.punctualLights[0].positionFalloff.w);
    float _1111 = fast::clamp(fma(-_1106, _1106, 1.0), 0.0, 1.0);
    float _1130 = fast::clamp(fma(dot(-_1102, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1141 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1111) * half(_1111)) / fast::max(_1097, 9.9999997473787516355514526367188e-05)) * half(_1130)) * half(_1130)), float3(65504.0));
    half _1196 = clamp(dot(_719, half3(_1102)), half(0.0), half(1.0));
    half _1200 = clamp(dot(_719, normalize(half3(_735) + half3(_1102))), half(0.0), half(1.0));
    half _1279 = clamp(dot(_900, half3(_1102)), half(0.0), half(1.0));
    half _1282 = _1279 * _1279;
    half4 _1852 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1282 * _1282, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1294 = _1852.x;
    half _1328 = half(8192.0) * fma(half(-float(_1196)), _896, _1196 + _896);
    half _1332 = half(1.0) / (_1042 * _1328);
    half _1339 = half(2048.0) * _1042;
    float3 _1397 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1400 = dot(_1397, _1397);
    float3 _1405 = _1397 * rsqrt(fast::max(_1400, 9.9999999392252902907785028219223e-09));
    float _1409 = _1400 * float(frame.punctualLights[1].positionFalloff.w);
    float _1414 = fast::clamp(fma(-_1409, _1409, 1.0), 0.0, 1.0);
    float _1433 = fast::clamp(fma(dot(-_1405, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1444 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1414) * half(_1414)) / fast::max(_1400, 9.9999997473787516355514526367188e-05)) * half(_1433)) * half(_1433)), float3(65504.0));
    half _1499 = clamp(dot(_719, half3(_1405)), half(0.0), half(1.0));
    half _1503 = clamp(dot(_719, normalize(half3(_735) + half3(_1405))), half(0.0), half(1.0));
    half _1582 = clamp(dot(_900, half3(_1405)), half(0.0), half(1.0));
    half _1585 = _1582 * _1582;
    half4 _1895 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1585 * _1585, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1597 = _1895.x;
    half _1631 = half(8192.0) * fma(half(-float(_1499)), _896, _1499 + _896);
    half _1635 = half(1.0) / (_1042 * _1631);
    half3 _1664 = (fma(half4(_1057).xyz, _1033 * _996, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_949).xyz * _939) * _998) + min(fma(_939 * ((_1294 * _1294) * half(5.092957973480224609375)), (half3(_1141) * _1196) * _998, (_1033 * ((((fma(_1332, _1328, half(2.0)) * pow(max(fma(half(-float(_1200)), _1200, half(1.0)), half(0.0)), half(0.5) * (_1332 * _1328))) * half(0.15915493667125701904296875)) * (_1196 * (_1332 * _1339))) * _1003)) * half3(_1141)), half3(float3(65504.0)))) + min(fma(_939 * ((_1597 * _1597) * half(5.092957973480224609375)), (half3(_1444) * _1499) * _998, (_1033 * ((((fma(_1635, _1631, half(2.0)) * pow(max(fma(half(-float(_1503)), _1503, half(1.0)), half(0.0)), half(0.5) * (_1635 * _1631))) * half(0.15915493667125701904296875)) * (_1499 * (_1635 * _1339))) * _1003)) * half3(_1444)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1664, half(1.0)));
    return out;
}

