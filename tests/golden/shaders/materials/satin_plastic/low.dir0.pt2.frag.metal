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
    half3 _742 = normalize(half3(in.v_normal));
    float3 _758 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _921 = max(dot(_742, half3(_758)), half(9.9999997473787516355514526367188e-05));
    half3 _925 = reflect(-half3(_758), _742);
    float4 _961 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_921, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _990 = facet_environment.sample(facet_environmentSmplr, float3(_925), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _940 = mix(half4(_961).xxx, half4(_961).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_961).y) - half(1.0))));
    half _1067 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1024 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_921, _1067)), level(0.0));
    half3 _1074 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1864 = half4(_1024);
    half _1037 = _1864.z;
    half _1039 = fma(half(-float(max(_1074.x, max(_1074.y, _1074.z)))), _1037, half(1.0));
    half _1083 = _1067 * _1067;
    half4 _1868 = half4(_1024);
    half _1044 = _1868.w;
    float4 _1098 = facet_environment.sample(facet_environmentSmplr, float3(_925), level(_1067 * (half(4.0) * (half(2.0) - _1067))));
    float3 _1135 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1138 = dot(_1135, _1135);
    float3 _1143 = _1135 * rsqrt(fast::max(_1138, 9.9999999392252902907785028219223e-09));
    float _1147 = _1138 * float(frame.punctualLights[0].positionFalloff.w);
    float _1152 = fast::clamp(fma(-_1147, _1147, 1.0), 0.0, 1.0);
    float _1171 = fast::clamp(fma(dot(-_1143, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1182 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1152) * half(_1152)) / fast::max(_1138, 9.9999997473787516355514526367188e-05)) * half(_1171)) * half(_1171)), float3(65504.0));
    half _1237 = clamp(dot(_742, half3(_1143)), half(0.0), half(1.0));
    half _1241 = clamp(dot(_742, normalize(half3(_758) + half3(_1143))), half(0.0), half(1.0));
    half _1320 = clamp(dot(_925, half3(_1143)), half(0.0), half(1.0));
    half _1323 = _1320 * _1320;
    half4 _1899 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1323 * _1323, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1335 = _1899.x;
    half _1369 = half(8192.0) * fma(half(-float(_1237)), _921, _1237 + _921);
    half _1373 = half(1.0) / (_1083 * _1369);
    half _1380 = half(2048.0) * _1083;
    float3 _1438 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1441 = dot(_1438, _1438);
    float3 _1446 = _1438 * rsqrt(fast::max(_1441, 9.9999999392252902907785028219223e-09));
    float _1450 = _1441 * float(frame.punctualLights[1].positionFalloff.w);
    float _1455 = fast::clamp(fma(-_1450, _1450, 1.0), 0.0, 1.0);
    float _1474 = fast::clamp(fma(dot(-_1446, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1485 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1455) * half(_1455)) / fast::max(_1441, 9.9999997473787516355514526367188e-05)) * half(_1474)) * half(_1474)), float3(65504.0));
    half _1540 = clamp(dot(_742, half3(_1446)), half(0.0), half(1.0));
    half _1544 = clamp(dot(_742, normalize(half3(_758) + half3(_1446))), half(0.0), half(1.0));
    half _1623 = clamp(dot(_925, half3(_1446)), half(0.0), half(1.0));
    half _1626 = _1623 * _1623;
    half4 _1942 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1626 * _1626, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1638 = _1942.x;
    half _1672 = half(8192.0) * fma(half(-float(_1540)), _921, _1540 + _921);
    half _1676 = half(1.0) / (_1083 * _1672);
    half3 _1705 = (fma(half4(_1098).xyz, _1074 * _1037, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_990).xyz * _940) * _1039) + min(fma(_940 * ((_1335 * _1335) * half(5.092957973480224609375)), (half3(_1182) * _1237) * _1039, (_1074 * ((((fma(_1373, _1369, half(2.0)) * pow(max(fma(half(-float(_1241)), _1241, half(1.0)), half(0.0)), half(0.5) * (_1373 * _1369))) * half(0.15915493667125701904296875)) * (_1237 * (_1373 * _1380))) * _1044)) * half3(_1182)), half3(float3(65504.0)))) + min(fma(_940 * ((_1638 * _1638) * half(5.092957973480224609375)), (half3(_1485) * _1540) * _1039, (_1074 * ((((fma(_1676, _1672, half(2.0)) * pow(max(fma(half(-float(_1544)), _1544, half(1.0)), half(0.0)), half(0.5) * (_1676 * _1672))) * half(0.15915493667125701904296875)) * (_1540 * (_1676 * _1380))) * _1044)) * half3(_1485)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1705, half(1.0)));
    return out;
}

