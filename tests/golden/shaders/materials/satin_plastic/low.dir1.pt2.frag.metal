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
    half _917 = max(dot(_719, half3(_735)), half(9.9999997473787516355514526367188e-05));
    half3 _921 = reflect(-half3(_735), _719);
    float4 _951 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_917, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _960 = mix(half4(_951).xxx, half4(_951).yyy, half3(float3(params.facet_f0)));
    float4 _970 = facet_environment.sample(facet_environmentSmplr, float3(_921), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1047 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1004 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_917, _1047)), level(0.0));
    half3 _1054 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2059 = half4(_1004);
    half _1017 = _2059.z;
    half _1019 = fma(half(-float(max(_1054.x, max(_1054.y, _1054.z)))), _1017, half(1.0));
    half _1063 = _1047 * _1047;
    half4 _2063 = half4(_1004);
    half _1024 = _2063.w;
    float4 _1078 = facet_environment.sample(facet_environmentSmplr, float3(_921), level(_1047 * (half(4.0) * (half(2.0) - _1047))));
    half3 _781 = half4(frame.lightDirection).xyz;
    half3 _793 = half4(frame.lightColor).xyz;
    half _1133 = clamp(dot(_719, _781), half(0.0), half(1.0));
    half _1137 = clamp(dot(_719, normalize(half3(_735) + _781)), half(0.0), half(1.0));
    half _1216 = clamp(dot(_921, _781), half(0.0), half(1.0));
    half _1219 = _1216 * _1216;
    half4 _2082 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1219 * _1219, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1231 = _2082.x;
    half _1265 = half(8192.0) * fma(half(-float(_1133)), _917, _1133 + _917);
    half _1269 = half(1.0) / (_1063 * _1265);
    half _1276 = half(2048.0) * _1063;
    float3 _1334 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1337 = dot(_1334, _1334);
    float3 _1342 = _1334 * rsqrt(fast::max(_1337, 9.9999999392252902907785028219223e-09));
    float _1346 = _1337 * float(frame.punctualLights[0].positionFalloff.w);
    float _1351 = fast::clamp(fma(-_1346, _1346, 1.0), 0.0, 1.0);
    float _1370 = fast::clamp(fma(dot(-_1342, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1381 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1351) * half(_1351)) / fast::max(_1337, 9.9999997473787516355514526367188e-05)) * half(_1370)) * half(_1370)), float3(65504.0));
    half _1436 = clamp(dot(_719, half3(_1342)), half(0.0), half(1.0));
    half _1440 = clamp(dot(_719, normalize(half3(_735) + half3(_1342))), half(0.0), half(1.0));
    half _1519 = clamp(dot(_921, half3(_1342)), half(0.0), half(1.0));
    half _1522 = _1519 * _1519;
    half4 _2123 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1522 * _1522, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1534 = _2123.x;
    half _1568 = half(8192.0) * fma(half(-float(_1436)), _917, _1436 + _917);
    half _1572 = half(1.0) / (_1063 * _1568);
    float3 _1637 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1640 = dot(_1637, _1637);
    float3 _1645 = _1637 * rsqrt(fast::max(_1640, 9.9999999392252902907785028219223e-09));
    float _1649 = _1640 * float(frame.punctualLights[1].positionFalloff.w);
    float _1654 = fast::clamp(fma(-_1649, _1649, 1.0), 0.0, 1.0);
    float _1673 = fast::clamp(fma(dot(-_1645, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1684 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1654) * half(_1654)) / fast::max(_1640, 9.9999997473787516355514526367188e-05)) * half(_1673)) * half(_1673)), float3(65504.0));
    half _1739 = clamp(dot(_719, half3(_1645)), half(0.0), half(1.0));
    half _1743 = clamp(dot(_719, normalize(half3(_735) + half3(_1645))), half(0.0), half(1.0));
    half _1822 = clamp(dot(_921, half3(_1645)), half(0.0), half(1.0));
    half _1825 = _1822 * _1822;
    half4 _2165 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1825 * _1825, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1837 = _2165.x;
    half _1871 = half(8192.0) * fma(half(-float(_1739)), _917, _1739 + _917);
    half _1875 = half(1.0) / (_1063 * _1871);
    half3 _1904 = ((fma(half4(_1078).xyz, _1054 * _1017, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_970).xyz * _960) * _1019) + min(fma(_960 * ((_1231 * _1231) * half(5.092957973480224609375)), (_793 * _1133) * _1019, (_1054 * ((((fma(_1269, _1265, half(2.0)) * pow(max(fma(half(-float(_1137)), _1137, half(1.0)), half(0.0)), half(0.5) * (_1269 * _1265))) * half(0.15915493667125701904296875)) * (_1133 * (_1269 * _1276))) * _1024)) * _793), half3(float3(65504.0)))) + min(fma(_960 * ((_1534 * _1534) * half(5.092957973480224609375)), (half3(_1381) * _1436) * _1019, (_1054 * ((((fma(_1572, _1568, half(2.0)) * pow(max(fma(half(-float(_1440)), _1440, half(1.0)), half(0.0)), half(0.5) * (_1572 * _1568))) * half(0.15915493667125701904296875)) * (_1436 * (_1572 * _1276))) * _1024)) * half3(_1381)), half3(float3(65504.0)))) + min(fma(_960 * ((_1837 * _1837) * half(5.092957973480224609375)), (half3(_1684) * _1739) * _1019, (_1054 * ((((fma(_1875, _1871, half(2.0)) * pow(max(fma(half(-float(_1743)), _1743, half(1.0)), half(0.0)), half(0.5) * (_1875 * _1871))) * half(0.15915493667125701904296875)) * (_1739 * (_1875 * _1276))) * _1024)) * half3(_1684)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1904, half(1.0)));
    return out;
}

