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
    half _936 = max(dot(_735, half3(_751)), half(9.9999997473787516355514526367188e-05));
    half3 _940 = reflect(-half3(_751), _735);
    float4 _976 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_936, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1005 = facet_environment.sample(facet_environmentSmplr, float3(_940), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _955 = mix(half4(_976).xxx, half4(_976).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_976).y) - half(1.0))));
    float4 _1037 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_936, half(params.facet_sheenRoughness))), level(0.0));
    half4 _2068 = half4(_1037);
    half _1050 = _2068.z;
    half _1052 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _1050, half(1.0));
    half4 _2072 = half4(_1037);
    half _1057 = _2072.w;
    float4 _1066 = facet_environment.sample(facet_environmentSmplr, float3(_940), level(params.facet_sheenLod));
    half3 _797 = half4(frame.lightDirection).xyz;
    half3 _809 = half4(frame.lightColor).xyz;
    half _1144 = clamp(dot(_735, _797), half(0.0), half(1.0));
    half _1148 = clamp(dot(_735, normalize(half3(_751) + _797)), half(0.0), half(1.0));
    half _1227 = clamp(dot(_940, _797), half(0.0), half(1.0));
    half _1230 = _1227 * _1227;
    half4 _2090 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1230 * _1230, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1242 = _2090.x;
    half _1276 = half(8192.0) * fma(half(-float(_1144)), _936, _1144 + _936);
    half _1280 = half(1.0) / (half(params.facet_sheenAlpha) * _1276);
    half _1287 = half(2048.0) * half(params.facet_sheenAlpha);
    float3 _1345 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1348 = dot(_1345, _1345);
    float3 _1353 = _1345 * rsqrt(fast::max(_1348, 9.9999999392252902907785028219223e-09));
    float _1357 = _1348 * float(frame.punctualLights[0].positionFalloff.w);
    float _1362 = fast::clamp(fma(-_1357, _1357, 1.0), 0.0, 1.0);
    float _1381 = fast::clamp(fma(dot(-_1353, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1392 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1362) * half(_1362)) / fast::max(_1348, 9.9999997473787516355514526367188e-05)) * half(_1381)) * half(_1381)), float3(65504.0));
    half _1447 = clamp(dot(_735, half3(_1353)), half(0.0), half(1.0));
    half _1451 = clamp(dot(_735, normalize(half3(_751) + half3(_1353))), half(0.0), half(1.0));
    half _1530 = clamp(dot(_940, half3(_1353)), half(0.0), half(1.0));
    half _1533 = _1530 * _1530;
    half4 _2134 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1533 * _1533, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1545 = _2134.x;
    half _1579 = half(8192.0) * fma(half(-float(_1447)), _936, _1447 + _936);
    half _1583 = half(1.0) / (half(params.facet_sheenAlpha) * _1579);
    half3 _1612 = (fma(half4(_1066).xyz, half3(float3(params.facet_sheenColor)) * _1050, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1005).xyz * _955) * _1052) + min(fma(_955 * ((_1242 * _1242) * half(5.092957973480224609375)), (_809 * _1144) * _1052, (half3(float3(params.facet_sheenColor)) * ((((fma(_1280, _1276, half(2.0)) * pow(max(fma(half(-float(_1148)), _1148, half(1.0)), half(0.0)), half(0.5) * (_1280 * _1276))) * half(0.15915493667125701904296875)) * (_1144 * (_1280 * _1287))) * _1057)) * _809), half3(float3(65504.0)))) + min(fma(_955 * ((_1545 * _1545) * half(5.092957973480224609375)), (half3(_1392) * _1447) * _1052, (half3(float3(params.facet_sheenColor)) * ((((fma(_1583, _1579, half(2.0)) * pow(max(fma(half(-float(_1451)), _1451, half(1.0)), half(0.0)), half(0.5) * (_1583 * _1579))) * half(0.15915493667125701904296875)) * (_1447 * (_1583 * _1287))) * _1057)) * half3(_1392)), half3(float3(65504.0)));
    float3 _1648 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1651 = dot(_1648, _1648);
    float3 _1656 = _1648 * rsqrt(fast::max(_1651, 9.9999999392252902907785028219223e-09));
    float _1660 = _1651 * float(frame.punctualLights[1].positionFalloff.w);
    float _1665 = fast::clamp(fma(-_1660, _1660, 1.0), 0.0, 1.0);
    float _1684 = fast::clamp(fma(dot(-_1656, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1695 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1665) * half(_1665)) / fast::max(_1651, 9.9999997473787516355514526367188e-05)) * half(_1684)) * half(_1684)), float3(65504.0));
    half _1750 = clamp(dot(_735, half3(_1656)), half(0.0), half(1.0));
    half _1754 = clamp(dot(_735, normalize(half3(_751) + half3(_1656))), half(0.0), half(1.0));
    half _1833 = clamp(dot(_940, half3(_1656)), half(0.0), half(1.0));
    half _1836 = _1833 * _1833;
    half4 _2178 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1836 * _1836, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1848 = _2178.x;
    half _1882 = half(8192.0) * fma(half(-float(_1750)), _936, _1750 + _936);
    half _1886 = half(1.0) / (half(params.facet_sheenAlpha) * _1882);
    out.fragColor = float4(half4(_1612 + min(fma(_955 * ((_1848 * _1848) * half(5.092957973480224609375)), (half3(_1695) * _1750) * _1052, (half3(float3(params.facet_sheenColor)) * ((((fma(_1886, _1882, half(2.0)) * pow(max(fma(half(-float(_1754)), _1754, half(1.0)), half(0.0)), half(0.5) * (_1886 * _1882))) * half(0.15915493667125701904296875)) * (_1750 * (_1886 * _1287))) * _1057)) * half3(_1695)), half3(float3(65504.0))), half(1.0)));
    return out;
}

