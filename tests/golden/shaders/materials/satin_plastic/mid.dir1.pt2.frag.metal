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

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _776 = normalize(half3(in.v_normal));
    float3 _792 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _973 = max(dot(_776, half3(_792)), half(9.9999997473787516355514526367188e-05));
    half3 _977 = reflect(-half3(_792), _776);
    float4 _1012 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_973, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1031 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1012).y) - half(1.0)));
    float4 _1038 = facet_environment.sample(facet_environmentSmplr, float3(_977), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1115 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1072 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_973, _1115)), level(0.0));
    half3 _1122 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2227 = half4(_1072);
    half _1085 = _2227.z;
    half _1087 = fma(half(-float(max(_1122.x, max(_1122.y, _1122.z)))), _1085, half(1.0));
    half _1131 = _1115 * _1115;
    half4 _2231 = half4(_1072);
    half _1092 = _2231.w;
    float4 _1143 = facet_environment.sample(facet_environmentSmplr, float3(_977), level(_1115 * half(4.0)));
    half3 _838 = half4(frame.lightDirection).xyz;
    half3 _850 = half4(frame.lightColor).xyz;
    half3 _1259 = normalize(half3(_792) + _838);
    half _1198 = clamp(dot(_776, _838), half(0.0), half(1.0));
    half _1202 = clamp(dot(_776, _1259), half(0.0), half(1.0));
    half3 _1322 = cross(_776, _1259) * half(64.0);
    half _1325 = half(64.0) * half(params.facet_alpha);
    half _1326 = _1202 * _1325;
    half _1297 = _1198 + _973;
    half _1302 = half(4096.0) * half(params.facet_alpha);
    half _1305 = half(6.283185482025146484375) * max(mix((half(2.0) * _1198) * _973, _1297, half(params.facet_alpha)), half(0.000244140625));
    half _1307 = _1302 / (fma(_1326, _1326, dot(_1322, _1322)) * _1305);
    half _1363 = half(8192.0) * fma(half(-float(_1198)), _973, _1297);
    half _1367 = half(1.0) / (_1131 * _1363);
    half _1374 = half(2048.0) * _1131;
    float3 _1432 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1435 = dot(_1432, _1432);
    float3 _1440 = _1432 * rsqrt(fast::max(_1435, 9.9999999392252902907785028219223e-09));
    float _1444 = _1435 * float(frame.punctualLights[0].positionFalloff.w);
    float _1449 = fast::clamp(fma(-_1444, _1444, 1.0), 0.0, 1.0);
    float _1468 = fast::clamp(fma(dot(-_1440, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1479 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1449) * half(_1449)) / fast::max(_1435, 9.9999997473787516355514526367188e-05)) * half(_1468)) * half(_1468)), float3(65504.0));
    half3 _1595 = normalize(half3(_792) + half3(_1440));
    half _1534 = clamp(dot(_776, half3(_1440)), half(0.0), half(1.0));
    half _1538 = clamp(dot(_776, _1595), half(0.0), half(1.0));
    half3 _1658 = cross(_776, _1595) * half(64.0);
    half _1662 = _1538 * _1325;
    half _1633 = _1534 + _973;
    half _1641 = half(6.283185482025146484375) * max(mix((half(2.0) * _1534) * _973, _1633, half(params.facet_alpha)), half(0.000244140625));
    half _1643 = _1302 / (fma(_1662, _1662, dot(_1658, _1658)) * _1641);
    half _1699 = half(8192.0) * fma(half(-float(_1534)), _973, _1633);
    half _1703 = half(1.0) / (_1131 * _1699);
    half3 _1732 = (fma(half4(_1143).xyz, _1122 * _1085, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1038).xyz * (mix(half4(_1012).xxx, half4(_1012).yyy, half3(float3(params.facet_f0))) * _1031)) * _1087) + min(fma((half3(float3(params.facet_f0)) * min(_1307 * (_1307 * _1305), half(65504.0))) * _1031, (_850 * _1198) * _1087, (_1122 * ((((fma(_1367, _1363, half(2.0)) * pow(max(fma(half(-float(_1202)), _1202, half(1.0)), half(0.0)), half(0.5) * (_1367 * _1363))) * half(0.15915493667125701904296875)) * (_1198 * (_1367 * _1374))) * _1092)) * _850), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) * min(_1643 * (_1643 * _1641), half(65504.0))) * _1031, (half3(_1479) * _1534) * _1087, (_1122 * ((((fma(_1703, _1699, half(2.0)) * pow(max(fma(half(-float(_1538)), _1538, half(1.0)), half(0.0)), half(0.5) * (_1703 * _1699))) * half(0.15915493667125701904296875)) * (_1534 * (_1703 * _1374))) * _1092)) * half3(_1479)), half3(float3(65504.0)));
    float3 _1768 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1771 = dot(_1768, _1768);
    float3 _1776 = _1768 * rsqrt(fast::max(_1771, 9.9999999392252902907785028219223e-09));
    float _1780 = _1771 * float(frame.punctualLights[1].positionFalloff.w);
    float _1785 = fast::clamp(fma(-_1780, _1780, 1.0), 0.0, 1.0);
    float _1804 = fast::clamp(fma(dot(-_1776, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1815 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1785) * half(_1785)) / fast::max(_1771, 9.9999997473787516355514526367188e-05)) * half(_1804)) * half(_1804)), float3(65504.0));
    half3 _1931 = normalize(half3(_792) + half3(_1776));
    half _1870 = clamp(dot(_776, half3(_1776)), half(0.0), half(1.0));
    half _1874 = clamp(dot(_776, _1931), half(0.0), half(1.0));
    half3 _1994 = cross(_776, _1931) * half(64.0);
    half _1998 = _1874 * _1325;
    half _1969 = _1870 + _973;
    half _1977 = half(6.283185482025146484375) * max(mix((half(2.0) * _1870) * _973, _1969, half(params.facet_alpha)), half(0.000244140625));
    half _1979 = _1302 / (fma(_1998, _1998, dot(_1994, _1994)) * _1977);
    half _2035 = half(8192.0) * fma(half(-float(_1870)), _973, _1969);
    half _2039 = half(1.0) / (_1131 * _2035);
    out.fragColor = float4(half4(_1732 + min(fma((half3(float3(params.facet_f0)) * min(_1979 * (_1979 * _1977), half(65504.0))) * _1031, (half3(_1815) * _1870) * _1087, (_1122 * ((((fma(_2039, _2035, half(2.0)) * pow(max(fma(half(-float(_1874)), _1874, half(1.0)), half(0.0)), half(0.5) * (_2039 * _2035))) * half(0.15915493667125701904296875)) * (_1870 * (_2039 * _1374))) * _1092)) * half3(_1815)), half3(float3(65504.0))), half(1.0)));
    return out;
}

