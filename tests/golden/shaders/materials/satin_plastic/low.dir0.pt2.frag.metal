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
    half3 _712 = normalize(half3(in.v_normal));
    float3 _728 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _890 = max(dot(_712, half3(_728)), half(9.9999997473787516355514526367188e-05));
    half3 _894 = reflect(-half3(_728), _712);
    float4 _924 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_890, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _933 = mix(half4(_924).xxx, half4(_924).yyy, half3(float3(params.facet_f0)));
    float4 _943 = facet_environment.sample(facet_environmentSmplr, float3(_894), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float4 _975 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_890, half(params.facet_sheenRoughness))), level(0.0));
    half4 _1779 = half4(_975);
    half _988 = _1779.z;
    half _990 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _988, half(1.0));
    half4 _1783 = half4(_975);
    half _995 = _1783.w;
    float4 _1004 = facet_environment.sample(facet_environmentSmplr, float3(_894), level(params.facet_sheenLod));
    float3 _1064 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1067 = dot(_1064, _1064);
    float3 _1072 = _1064 * rsqrt(fast::max(_1067, 9.9999999392252902907785028219223e-09));
    float _1076 = _1067 * float(frame.punctualLights[0].positionFalloff.w);
    float _1081 = fast::clamp(fma(-_1076, _1076, 1.0), 0.0, 1.0);
    float _1100 = fast::clamp(fma(dot(-_1072, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1111 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1081) * half(_1081)) / fast::max(_1067, 9.9999997473787516355514526367188e-05)) * half(_1100)) * half(_1100)), float3(65504.0));
    half _1166 = clamp(dot(_712, half3(_1072)), half(0.0), half(1.0));
    half _1170 = clamp(dot(_712, normalize(half3(_728) + half3(_1072))), half(0.0), half(1.0));
    half _1249 = clamp(dot(_894, half3(_1072)), half(0.0), half(1.0));
    half _1252 = _1249 * _1249;
    half4 _1813 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1252 * _1252, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1264 = _1813.x;
    half _1298 = half(8192.0) * fma(half(-float(_1166)), _890, _1166 + _890);
    half _1302 = half(1.0) / (half(params.facet_sheenAlpha) * _1298);
    half _1309 = half(2048.0) * half(params.facet_sheenAlpha);
    float3 _1367 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1370 = dot(_1367, _1367);
    float3 _1375 = _1367 * rsqrt(fast::max(_1370, 9.9999999392252902907785028219223e-09));
    float _1379 = _1370 * float(frame.punctualLights[1].positionFalloff.w);
    float _1384 = fast::clamp(fma(-_1379, _1379, 1.0), 0.0, 1.0);
    float _1403 = fast::clamp(fma(dot(-_1375, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1414 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1384) * half(_1384)) / fast::max(_1370, 9.9999997473787516355514526367188e-05)) * half(_1403)) * half(_1403)), float3(65504.0));
    half _1469 = clamp(dot(_712, half3(_1375)), half(0.0), half(1.0));
    half _1473 = clamp(dot(_712, normalize(half3(_728) + half3(_1375))), half(0.0), half(1.0));
    half _1552 = clamp(dot(_894, half3(_1375)), half(0.0), half(1.0));
    half _1555 = _1552 * _1552;
    half4 _1859 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1555 * _1555, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1567 = _1859.x;
    half _1601 = half(8192.0) * fma(half(-float(_1469)), _890, _1469 + _890);
    half _1605 = half(1.0) / (half(params.facet_sheenAlpha) * _1601);
    half3 _1634 = (fma(half4(_1004).xyz, half3(float3(params.facet_sheenColor)) * _988, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_943).xyz * _933) * _990) + min(fma(_933 * ((_1264 * _1264) * half(5.092957973480224609375)), (half3(_1111) * _1166) * _990, (half3(float3(params.facet_sheenColor)) * ((((fma(_1302, _1298, half(2.0)) * pow(max(fma(half(-float(_1170)), _1170, half(1.0)), half(0.0)), half(0.5) * (_1302 * _1298))) * half(0.15915493667125701904296875)) * (_1166 * (_1302 * _1309))) * _995)) * half3(_1111)), half3(float3(65504.0)))) + min(fma(_933 * ((_1567 * _1567) * half(5.092957973480224609375)), (half3(_1414) * _1469) * _990, (half3(float3(params.facet_sheenColor)) * ((((fma(_1605, _1601, half(2.0)) * pow(max(fma(half(-float(_1473)), _1473, half(1.0)), half(0.0)), half(0.5) * (_1605 * _1601))) * half(0.15915493667125701904296875)) * (_1469 * (_1605 * _1309))) * _995)) * half3(_1414)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1634, half(1.0)));
    return out;
}

