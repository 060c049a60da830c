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
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
    float facet_sheenRoughness;
    float facet_sheenAlpha;
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
    half3 _735 = normalize(half3(in.v_normal));
    float3 _751 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _915 = max(dot(_735, half3(_751)), half(9.9999997473787516355514526367188e-05));
    half3 _919 = reflect(-half3(_751), _735);
    float4 _955 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_915, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _984 = facet_environment.sample(facet_environmentSmplr, float3(_919), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _934 = mix(half4(_955).xxx, half4(_955).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_955).y) - half(1.0))));
    float4 _1016 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_915, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1826 = half4(_1016);
    half _1029 = _1826.z;
    half _1031 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _1029, half(1.0));
    half4 _1830 = half4(_1016);
    half _1036 = _1830.w;
    float4 _1045 = facet_environment.sample(facet_environmentSmplr, float3(_919), level(params.facet_sheenLod));
    float3 _1105 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1108 = dot(_1105, _1105);
    float3 _1113 = _1105 * rsqrt(fast::max(_1108, 9.9999999392252902907785028219223e-09));
    float _1117 = _1108 * float(frame.punctualLights[0].positionFalloff.w);
    float _1122 = fast::clamp(fma(-_1117, _1117, 1.0), 0.0, 1.0);
    float _1141 = fast::clamp(fma(dot(-_1113, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1152 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1122) * half(_1122)) / fast::max(_1108, 9.9999997473787516355514526367188e-05)) * half(_1141)) * half(_1141)), float3(65504.0));
    half _1207 = clamp(dot(_735, half3(_1113)), half(0.0), half(1.0));
    half _1211 = clamp(dot(_735, normalize(half3(_751) + half3(_1113))), half(0.0), half(1.0));
    half _1290 = clamp(dot(_919, half3(_1113)), half(0.0), half(1.0));
    half _1293 = _1290 * _1290;
    half4 _1860 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1293 * _1293, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1305 = _1860.x;
    half _1339 = half(8192.0) * fma(half(-float(_1207)), _915, _1207 + _915);
    half _1343 = half(1.0) / (half(params.facet_sheenAlpha) * _1339);
    half _1350 = half(2048.0) * half(params.facet_sheenAlpha);
    float3 _1408 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1411 = dot(_1408, _1408);
    float3 _1416 = _1408 * rsqrt(fast::max(_1411, 9.9999999392252902907785028219223e-09));
    float _1420 = _1411 * float(frame.punctualLights[1].positionFalloff.w);
    float _1425 = fast::clamp(fma(-_1420, _1420, 1.0), 0.0, 1.0);
    float _1444 = fast::clamp(fma(dot(-_1416, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1455 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1425) * half(_1425)) / fast::max(_1411, 9.9999997473787516355514526367188e-05)) * half(_1444)) * half(_1444)), float3(65504.0));
    half _1510 = clamp(dot(_735, half3(_1416)), half(0.0), half(1.0));
    half _1514 = clamp(dot(_735, normalize(half3(_751) + half3(_1416))), half(0.0), half(1.0));
    half _1593 = clamp(dot(_919, half3(_1416)), half(0.0), half(1.0));
    half _1596 = _1593 * _1593;
    half4 _1906 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1596 * _1596, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1608 = _1906.x;
    half _1642 = half(8192.0) * fma(half(-float(_1510)), _915, _1510 + _915);
    half _1646 = half(1.0) / (half(params.facet_sheenAlpha) * _1642);
    half3 _1675 = (fma(half4(_1045).xyz, half3(float3(params.facet_sheenColor)) * _1029, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_984).xyz * _934) * _1031) + min(fma(_934 * ((_1305 * _1305) * half(5.092957973480224609375)), (half3(_1152) * _1207) * _1031, (half3(float3(params.facet_sheenColor)) * ((((fma(_1343, _1339, half(2.0)) * pow(max(fma(half(-float(_1211)), _1211, half(1.0)), half(0.0)), half(0.5) * (_1343 * _1339))) * half(0.15915493667125701904296875)) * (_1207 * (_1343 * _1350))) * _1036)) * half3(_1152)), half3(float3(65504.0)))) + min(fma(_934 * ((_1608 * _1608) * half(5.092957973480224609375)), (half3(_1455) * _1510) * _1031, (half3(float3(params.facet_sheenColor)) * ((((fma(_1646, _1642, half(2.0)) * pow(max(fma(half(-float(_1514)), _1514, half(1.0)), half(0.0)), half(0.5) * (_1646 * _1642))) * half(0.15915493667125701904296875)) * (_1510 * (_1646 * _1350))) * _1036)) * half3(_1455)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1675, half(1.0)));
    return out;
}

