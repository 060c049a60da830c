#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 paint;
    float roughness;
    float coat;
    float coatRoughness;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
    packed_float3 facet_f0;
    float facet_alpha;
    float facet_clearCoat;
    float facet_clearCoatAlpha;
    float facet_clearCoatLod;
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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texture2d<float> facet_specularLut [[texture(1)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_specularLutSmplr [[sampler(1)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _832 = normalize(half3(in.v_normal));
    float3 _838 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1055 = max(dot(_832, half3(_838)), half(9.9999997473787516355514526367188e-05));
    half3 _1059 = reflect(-half3(_838), _832);
    float4 _1095 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1055, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1124 = facet_environment.sample(facet_environmentSmplr, float3(_1059), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half3 _1074 = mix(half4(_1095).xxx, half4(_1095).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1095).y) - half(1.0))));
    half _1171 = half(1.0) - _1055;
    half _1174 = _1171 * _1171;
    half _1181 = fma(half(0.959999978542327880859375), (_1174 * _1174) * _1171, half(0.039999999105930328369140625));
    half _1151 = fma(half(-float(_1181)), half(params.facet_clearCoat), half(1.0));
    float4 _1159 = facet_environment.sample(facet_environmentSmplr, float3(_1059), level(params.facet_clearCoatLod));
    float3 _1221 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1224 = dot(_1221, _1221);
    float3 _1229 = _1221 * rsqrt(fast::max(_1224, 9.9999999392252902907785028219223e-09));
    float _1233 = _1224 * float(frame.punctualLights[0].positionFalloff.w);
    float _1238 = fast::clamp(fma(-_1233, _1233, 1.0), 0.0, 1.0);
    float _1257 = fast::clamp(fma(dot(-_1229, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1389 = normalize(half3(_838) + half3(_1229));
    half _1333 = clamp(dot(half3(_1229), _1389), half(0.0), half(1.0));
    half _1414 = clamp(dot(_1059, half3(_1229)), half(0.0), half(1.0));
    half _1417 = _1414 * _1414;
    half4 _2100 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1417 * _1417, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1429 = _2100.x;
    half3 _1512 = cross(_832, _1389) * half(64.0);
    half _1514 = half(64.0) * half(params.facet_clearCoatAlpha);
    half _1516 = _1514 * clamp(dot(_832, _1389), half(0.0), half(1.0));
    half _1468 = half(12.56637096405029296875) * max(_1333 * _1333, half(6.103515625e-05));
    half _1470 = half(4096.0) * half(params.facet_clearCoatAlpha);
    half _1474 = _1470 / (fma(_1516, _1516, dot(_1512, _1512)) * _1468);
    half _1484 = half(1.0) - _1333;
    half _1487 = _1484 * _1484;
    half _1492 = half(0.959999978542327880859375) * half(params.facet_clearCoat);
    float3 _1582 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1585 = dot(_1582, _1582);
    float3 _1590 = _1582 * rsqrt(fast::max(_1585, 9.9999999392252902907785028219223e-09));
    float _1594 = _1585 * float(frame.punctualLights[1].positionFalloff.w);
    float _1599 = fast::clamp(fma(-_1594, _1594, 1.0), 0.0, 1.0);
    float _1618 = fast::clamp(fma(dot(-_1590, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    half3 _1750 = normalize(half3(_838) + half3(_1590));
    half _1694 = clamp(dot(half3(_1590), _1750), half(0.0), half(1.0));
    half _1775 = clamp(dot(_1059, half3(_1590)), half(0.0), half(1.0));
    half _1778 = _1775 * _1775;
    half4 _2147 = half4(facet_specularLut.sample(facet_specularLutSmplr, float2(fma(half2(_1778 * _1778, half(params.facet_perceptualRoughness)), half2(float2(0.9921875, 0.984375)), half2(float2(0.00390625, 0.0078125)))), level(0.0)));
    half _1790 = _2147.x;
    half3 _1873 = cross(_832, _1750) * half(64.0);
    half _1877 = _1514 * clamp(dot(_832, _1750), half(0.0), half(1.0));
    half _1829 = half(12.56637096405029296875) * max(_1694 * _1694, half(6.103515625e-05));
    half _1835 = _1470 / (fma(_1877, _1877, dot(_1873, _1873)) * _1829);
    half _1845 = half(1.0) - _1694;
    half _1848 = _1845 * _1845;
    half3 _1907 = (mix(half4(_1124).xyz * _1074, half4(_1159).xyz, half3(_1181 * half(params.facet_clearCoat))) + min(min(((_1074 * ((_1429 * _1429) * half(5.092957973480224609375))) * _1151) + half3(min(_1474 * (_1474 * _1468), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1492 * ((_1487 * _1487) * _1484))), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1238) * half(_1238)) / fast::max(_1224, 9.9999997473787516355514526367188e-05)) * half(_1257)) * half(_1257)), float3(65504.0))) * clamp(dot(_832, half3(_1229)), half(0.0), half(1.0))), half3(float3(65504.0)))) + min(min(((_1074 * ((_1790 * _1790) * half(5.092957973480224609375))) * _1151) + half3(min(_1835 * (_1835 * _1829), half(65504.0)) * fma(half(0.039999999105930328369140625), half(params.facet_clearCoat), _1492 * ((_1848 * _1848) * _1845))), half3(float3(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1599) * half(_1599)) / fast::max(_1585, 9.9999997473787516355514526367188e-05)) * half(_1618)) * half(_1618)), float3(65504.0))) * clamp(dot(_832, half3(_1590)), half(0.0), half(1.0))), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1907, half(1.0)));
    return out;
}

