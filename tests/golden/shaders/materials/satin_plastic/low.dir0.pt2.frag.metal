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
    float facet_environmentLod;
    float facet_ggxAlphaScaled;
    float facet_ziomaRoughnessFactor;
    char _m11_pad[4];
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
    half3 _698 = normalize(half3(in.v_normal));
    float3 _714 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _874 = max(dot(_698, half3(_714)), half(9.9999997473787516355514526367188e-05));
    half3 _878 = reflect(-half3(_714), _698);
    float4 _911 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_874, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _920 = mix(half4(_911).xxx, half4(_911).yyy, half3(float3(params.facet_f0)));
    float4 _889 = facet_environment.sample(facet_environmentSmplr, float3(_878), level(params.facet_environmentLod));
    float4 _951 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_874, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1751 = half4(_951);
    half _964 = _1751.z;
    half _966 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _964, half(1.0));
    half4 _1755 = half4(_951);
    half _971 = _1755.w;
    float4 _980 = facet_environment.sample(facet_environmentSmplr, float3(_878), level(params.facet_sheenLod));
    float3 _1040 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1043 = dot(_1040, _1040);
    float3 _1048 = _1040 * rsqrt(fast::max(_1043, 9.9999999392252902907785028219223e-09));
    float _1052 = _1043 * float(frame.punctualLights[0].positionFalloff.w);
    float _1057 = fast::clamp(fma(-_1052, _1052, 1.0), 0.0, 1.0);
    float _1076 = fast::clamp(fma(dot(-_1048, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1087 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1057) * half(_1057)) / fast::max(_1043, 9.9999997473787516355514526367188e-05)) * half(_1076)) * half(_1076)), float3(65504.0));
    half _1139 = clamp(dot(_698, half3(_1048)), half(0.0), half(1.0));
    half _1146 = clamp(dot(_698, normalize(half3(_714) + half3(_1048))), half(0.0), half(1.0));
    half _1225 = clamp(dot(_878, half3(_1048)), half(0.0), half(1.0));
    half _1228 = _1225 * _1225;
    half4 _1785 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1228 * _1228, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1240 = _1785.x;
    half _1274 = half(8192.0) * fma(half(-float(_1139)), _874, _1139 + _874);
    half _1278 = half(1.0) / (half(params.facet_sheenAlpha) * _1274);
    half _1285 = half(2048.0) * half(params.facet_sheenAlpha);
    float3 _1343 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1346 = dot(_1343, _1343);
    float3 _1351 = _1343 * rsqrt(fast::max(_1346, 9.9999999392252902907785028219223e-09));
    float _1355 = _1346 * float(frame.punctualLights[1].positionFalloff.w);
    float _1360 = fast::clamp(fma(-_1355, _1355, 1.0), 0.0, 1.0);
    float _1379 = fast::clamp(fma(dot(-_1351, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1390 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1360) * half(_1360)) / fast::max(_1346, 9.9999997473787516355514526367188e-05)) * half(_1379)) * half(_1379)), float3(65504.0));
    half _1442 = clamp(dot(_698, half3(_1351)), half(0.0), half(1.0));
    half _1449 = clamp(dot(_698, normalize(half3(_714) + half3(_1351))), half(0.0), half(1.0));
    half _1528 = clamp(dot(_878, half3(_1351)), half(0.0), half(1.0));
    half _1531 = _1528 * _1528;
    half4 _1831 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1531 * _1531, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1543 = _1831.x;
    half _1577 = half(8192.0) * fma(half(-float(_1442)), _874, _1442 + _874);
    half _1581 = half(1.0) / (half(params.facet_sheenAlpha) * _1577);
    half3 _1610 = (fma(half4(_980).xyz, half3(float3(params.facet_sheenColor)) * _964, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_889).xyz * _920) * _966) + min(fma(_920 * ((_1240 * _1240) * half(5.092957973480224609375)), (half3(_1087) * _1139) * _966, (half3(float3(params.facet_sheenColor)) * ((((fma(_1278, _1274, half(2.0)) * pow(max(fma(half(-float(_1146)), _1146, half(1.0)), half(0.0)), half(0.5) * (_1278 * _1274))) * half(0.15915493667125701904296875)) * (_1139 * (_1278 * _1285))) * _971)) * half3(_1087)), half3(float3(65504.0)))) + min(fma(_920 * ((_1543 * _1543) * half(5.092957973480224609375)), (half3(_1390) * _1442) * _966, (half3(float3(params.facet_sheenColor)) * ((((fma(_1581, _1577, half(2.0)) * pow(max(fma(half(-float(_1449)), _1449, half(1.0)), half(0.0)), half(0.5) * (_1581 * _1577))) * half(0.15915493667125701904296875)) * (_1442 * (_1581 * _1285))) * _971)) * half3(_1390)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1610, half(1.0)));
    return out;
}

