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
    half _895 = max(dot(_698, half3(_714)), half(9.9999997473787516355514526367188e-05));
    half3 _899 = reflect(-half3(_714), _698);
    float4 _932 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_895, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _941 = mix(half4(_932).xxx, half4(_932).yyy, half3(float3(params.facet_f0)));
    float4 _910 = facet_environment.sample(facet_environmentSmplr, float3(_899), level(params.facet_environmentLod));
    float4 _972 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_895, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1993 = half4(_972);
    half _985 = _1993.z;
    half _987 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _985, half(1.0));
    half4 _1997 = half4(_972);
    half _992 = _1997.w;
    float4 _1001 = facet_environment.sample(facet_environmentSmplr, float3(_899), level(params.facet_sheenLod));
    half3 _760 = half4(frame.lightDirection).xyz;
    half3 _772 = half4(frame.lightColor).xyz;
    half _1076 = clamp(dot(_698, _760), half(0.0), half(1.0));
    half _1083 = clamp(dot(_698, normalize(half3(_714) + _760)), half(0.0), half(1.0));
    half _1162 = clamp(dot(_899, _760), half(0.0), half(1.0));
    half _1165 = _1162 * _1162;
    half4 _2015 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1165 * _1165, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1177 = _2015.x;
    half _1211 = half(8192.0) * fma(half(-float(_1076)), _895, _1076 + _895);
    half _1215 = half(1.0) / (half(params.facet_sheenAlpha) * _1211);
    half _1222 = half(2048.0) * half(params.facet_sheenAlpha);
    float3 _1280 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1283 = dot(_1280, _1280);
    float3 _1288 = _1280 * rsqrt(fast::max(_1283, 9.9999999392252902907785028219223e-09));
    float _1292 = _1283 * float(frame.punctualLights[0].positionFalloff.w);
    float _1297 = fast::clamp(fma(-_1292, _1292, 1.0), 0.0, 1.0);
    float _1316 = fast::clamp(fma(dot(-_1288, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1327 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1297) * half(_1297)) / fast::max(_1283, 9.9999997473787516355514526367188e-05)) * half(_1316)) * half(_1316)), float3(65504.0));
    half _1379 = clamp(dot(_698, half3(_1288)), half(0.0), half(1.0));
    half _1386 = clamp(dot(_698, normalize(half3(_714) + half3(_1288))), half(0.0), half(1.0));
    half _1465 = clamp(dot(_899, half3(_1288)), half(0.0), half(1.0));
    half _1468 = _1465 * _1465;
    half4 _2059 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1468 * _1468, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1480 = _2059.x;
    half _1514 = half(8192.0) * fma(half(-float(_1379)), _895, _1379 + _895);
    half _1518 = half(1.0) / (half(params.facet_sheenAlpha) * _1514);
    half3 _1547 = (fma(half4(_1001).xyz, half3(float3(params.facet_sheenColor)) * _985, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_910).xyz * _941) * _987) + min(fma(_941 * ((_1177 * _1177) * half(5.092957973480224609375)), (_772 * _1076) * _987, (half3(float3(params.facet_sheenColor)) * ((((fma(_1215, _1211, half(2.0)) * pow(max(fma(half(-float(_1083)), _1083, half(1.0)), half(0.0)), half(0.5) * (_1215 * _1211))) * half(0.15915493667125701904296875)) * (_1076 * (_1215 * _1222))) * _992)) * _772), half3(float3(65504.0)))) + min(fma(_941 * ((_1480 * _1480) * half(5.092957973480224609375)), (half3(_1327) * _1379) * _987, (half3(float3(params.facet_sheenColor)) * ((((fma(_1518, _1514, half(2.0)) * pow(max(fma(half(-float(_1386)), _1386, half(1.0)), half(0.0)), half(0.5) * (_1518 * _1514))) * half(0.15915493667125701904296875)) * (_1379 * (_1518 * _1222))) * _992)) * half3(_1327)), half3(float3(65504.0)));
    float3 _1583 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1586 = dot(_1583, _1583);
    float3 _1591 = _1583 * rsqrt(fast::max(_1586, 9.9999999392252902907785028219223e-09));
    float _1595 = _1586 * float(frame.punctualLights[1].positionFalloff.w);
    float _1600 = fast::clamp(fma(-_1595, _1595, 1.0), 0.0, 1.0);
    float _1619 = fast::clamp(fma(dot(-_1591, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1630 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1600) * half(_1600)) / fast::max(_1586, 9.9999997473787516355514526367188e-05)) * half(_1619)) * half(_1619)), float3(65504.0));
    half _1682 = clamp(dot(_698, half3(_1591)), half(0.0), half(1.0));
    half _1689 = clamp(dot(_698, normalize(half3(_714) + half3(_1591))), half(0.0), half(1.0));
    half _1768 = clamp(dot(_899, half3(_1591)), half(0.0), half(1.0));
    half _1771 = _1768 * _1768;
    half4 _2103 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1771 * _1771, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1783 = _2103.x;
    half _1817 = half(8192.0) * fma(half(-float(_1682)), _895, _1682 + _895);
    half _1821 = half(1.0) / (half(params.facet_sheenAlpha) * _1817);
    out.fragColor = float4(half4(_1547 + min(fma(_941 * ((_1783 * _1783) * half(5.092957973480224609375)), (half3(_1630) * _1682) * _987, (half3(float3(params.facet_sheenColor)) * ((((fma(_1821, _1817, half(2.0)) * pow(max(fma(half(-float(_1689)), _1689, half(1.0)), half(0.0)), half(0.5) * (_1821 * _1817))) * half(0.15915493667125701904296875)) * (_1682 * (_1821 * _1222))) * _992)) * half3(_1630)), half3(float3(65504.0))), half(1.0)));
    return out;
}

