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
    half3 _786 = normalize(half3(in.v_normal));
    float3 _802 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _965 = max(dot(_786, half3(_802)), half(9.9999997473787516355514526367188e-05));
    half3 _969 = reflect(-half3(_802), _786);
    float4 _1005 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_965, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1031 = facet_environment.sample(facet_environmentSmplr, float3(_969), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half3 _984 = mix(half4(_1005).xxx, half4(_1005).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1005).y) - half(1.0))));
    half _1104 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1064 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_965, _1104)), level(0.0));
    half3 _1111 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2044 = half4(_1064);
    half _1077 = _2044.z;
    half _1079 = fma(half(-float(max(_1111.x, max(_1111.y, _1111.z)))), _1077, half(1.0));
    half4 _2048 = half4(_1064);
    half _1081 = _2048.w;
    float4 _1118 = facet_environment.sample(facet_environmentSmplr, float3(_969), level(_1104 * half(4.0)));
    float3 _1155 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1158 = dot(_1155, _1155);
    float3 _1163 = _1155 * rsqrt(fast::max(_1158, 9.9999999392252902907785028219223e-09));
    float _1167 = _1158 * float(frame.punctualLights[0].positionFalloff.w);
    float _1172 = fast::clamp(fma(-_1167, _1167, 1.0), 0.0, 1.0);
    float _1191 = fast::clamp(fma(dot(-_1163, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1202 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1172) * half(_1172)) / fast::max(_1158, 9.9999997473787516355514526367188e-05)) * half(_1191)) * half(_1191)), float3(65504.0));
    half _1281 = clamp(dot(_786, half3(_1163)), half(0.0), half(1.0));
    half _1355 = clamp(dot(_969, half3(_1163)), half(0.0), half(1.0));
    half _1358 = _1355 * _1355;
    half4 _2074 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1358 * _1358, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1370 = _2074.x;
    half _1408 = clamp(dot(_786, normalize(half3(_802) + half3(_1163))), half(0.0), half(1.0));
    half _1435 = _1104 * _1104;
    half _1455 = half(8192.0) * fma(half(-float(_1281)), _965, _1281 + _965);
    half _1459 = half(1.0) / (_1435 * _1455);
    half _1466 = half(2048.0) * _1435;
    float3 _1536 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1539 = dot(_1536, _1536);
    float3 _1544 = _1536 * rsqrt(fast::max(_1539, 9.9999999392252902907785028219223e-09));
    float _1548 = _1539 * float(frame.punctualLights[1].positionFalloff.w);
    float _1553 = fast::clamp(fma(-_1548, _1548, 1.0), 0.0, 1.0);
    float _1572 = fast::clamp(fma(dot(-_1544, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1583 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1553) * half(_1553)) / fast::max(_1539, 9.9999997473787516355514526367188e-05)) * half(_1572)) * half(_1572)), float3(65504.0));
    half _1662 = clamp(dot(_786, half3(_1544)), half(0.0), half(1.0));
    half _1736 = clamp(dot(_969, half3(_1544)), half(0.0), half(1.0));
    half _1739 = _1736 * _1736;
    half4 _2118 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1739 * _1739, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1751 = _2118.x;
    half _1789 = clamp(dot(_786, normalize(half3(_802) + half3(_1544))), half(0.0), half(1.0));
    half _1836 = half(8192.0) * fma(half(-float(_1662)), _965, _1662 + _965);
    half _1840 = half(1.0) / (_1435 * _1836);
    half3 _1881 = (fma(half4(_1118).xyz, _1111 * _1077, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1031).xyz * _984) * _1079) + (min((_984 * ((_1370 * _1370) * half(5.092957973480224609375))) * ((half3(_1202) * _1281) * _1079), half3(float3(65504.0))) + min((_1111 * ((((fma(_1459, _1455, half(2.0)) * pow(max(fma(half(-float(_1408)), _1408, half(1.0)), half(0.0)), half(0.5) * (_1459 * _1455))) * half(0.15915493667125701904296875)) * (_1281 * (_1459 * _1466))) * _1081)) * half3(_1202), half3(float3(65504.0))))) + (min((_984 * ((_1751 * _1751) * half(5.092957973480224609375))) * ((half3(_1583) * _1662) * _1079), half3(float3(65504.0))) + min((_1111 * ((((fma(_1840, _1836, half(2.0)) * pow(max(fma(half(-float(_1789)), _1789, half(1.0)), half(0.0)), half(0.5) * (_1840 * _1836))) * half(0.15915493667125701904296875)) * (_1662 * (_1840 * _1466))) * _1081)) * half3(_1583), half3(float3(65504.0))));
    out.fragColor = float4(half4(_1881, half(1.0)));
    return out;
}

