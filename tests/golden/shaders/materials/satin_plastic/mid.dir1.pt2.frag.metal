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
    half3 _751 = normalize(half3(in.v_normal));
    float3 _767 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _946 = max(dot(_751, half3(_767)), half(9.9999997473787516355514526367188e-05));
    half3 _950 = reflect(-half3(_767), _751);
    float4 _979 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_946, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _998 = facet_environment.sample(facet_environmentSmplr, float3(_950), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1075 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1032 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_946, _1075)), level(0.0));
    half3 _1082 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2171 = half4(_1032);
    half _1045 = _2171.z;
    half _1047 = fma(half(-float(max(_1082.x, max(_1082.y, _1082.z)))), _1045, half(1.0));
    half _1091 = _1075 * _1075;
    half4 _2175 = half4(_1032);
    half _1052 = _2175.w;
    float4 _1106 = facet_environment.sample(facet_environmentSmplr, float3(_950), level(_1075 * (half(4.0) * (half(2.0) - _1075))));
    half3 _813 = half4(frame.lightDirection).xyz;
    half3 _825 = half4(frame.lightColor).xyz;
    half3 _1219 = normalize(half3(_767) + _813);
    half _1161 = clamp(dot(_751, _813), half(0.0), half(1.0));
    half _1165 = clamp(dot(_751, _1219), half(0.0), half(1.0));
    half4 _1288 = half4(cross(_751, _1219), half(params.facet_alpha) * _1165) * half(64.0);
    half _1257 = _1161 + _946;
    half _1262 = half(4096.0) * half(params.facet_alpha);
    half _1265 = half(6.283185482025146484375) * max(mix((half(2.0) * _1161) * _946, _1257, half(params.facet_alpha)), half(0.000244140625));
    half _1267 = _1262 / (dot(_1288, _1288) * _1265);
    half _1321 = half(8192.0) * fma(half(-float(_1161)), _946, _1257);
    half _1325 = half(1.0) / (_1091 * _1321);
    half _1332 = half(2048.0) * _1091;
    float3 _1390 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1393 = dot(_1390, _1390);
    float3 _1398 = _1390 * rsqrt(fast::max(_1393, 9.9999999392252902907785028219223e-09));
    float _1402 = _1393 * float(frame.punctualLights[0].positionFalloff.w);
    float _1407 = fast::clamp(fma(-_1402, _1402, 1.0), 0.0, 1.0);
    float _1426 = fast::clamp(fma(dot(-_1398, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1437 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1407) * half(_1407)) / fast::max(_1393, 9.9999997473787516355514526367188e-05)) * half(_1426)) * half(_1426)), float3(65504.0));
    half3 _1550 = normalize(half3(_767) + half3(_1398));
    half _1492 = clamp(dot(_751, half3(_1398)), half(0.0), half(1.0));
    half _1496 = clamp(dot(_751, _1550), half(0.0), half(1.0));
    half4 _1619 = half4(cross(_751, _1550), half(params.facet_alpha) * _1496) * half(64.0);
    half _1588 = _1492 + _946;
    half _1596 = half(6.283185482025146484375) * max(mix((half(2.0) * _1492) * _946, _1588, half(params.facet_alpha)), half(0.000244140625));
    half _1598 = _1262 / (dot(_1619, _1619) * _1596);
    half _1652 = half(8192.0) * fma(half(-float(_1492)), _946, _1588);
    half _1656 = half(1.0) / (_1091 * _1652);
    half3 _1685 = (fma(half4(_1106).xyz, _1082 * _1045, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_998).xyz * mix(half4(_979).xxx, half4(_979).yyy, half3(float3(params.facet_f0)))) * _1047) + min(fma(half3(float3(params.facet_f0)) * min(_1267 * (_1267 * _1265), half(65504.0)), (_825 * _1161) * _1047, (_1082 * ((((fma(_1325, _1321, half(2.0)) * pow(max(fma(half(-float(_1165)), _1165, half(1.0)), half(0.0)), half(0.5) * (_1325 * _1321))) * half(0.15915493667125701904296875)) * (_1161 * (_1325 * _1332))) * _1052)) * _825), half3(float3(65504.0)))) + min(fma(half3(float3(params.facet_f0)) * min(_1598 * (_1598 * _1596), half(65504.0)), (half3(_1437) * _1492) * _1047, (_1082 * ((((fma(_1656, _1652, half(2.0)) * pow(max(fma(half(-float(_1496)), _1496, half(1.0)), half(0.0)), half(0.5) * (_1656 * _1652))) * half(0.15915493667125701904296875)) * (_1492 * (_1656 * _1332))) * _1052)) * half3(_1437)), half3(float3(65504.0)));
    float3 _1721 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1724 = dot(_1721, _1721);
    float3 _1729 = _1721 * rsqrt(fast::max(_1724, 9.9999999392252902907785028219223e-09));
    float _1733 = _1724 * float(frame.punctualLights[1].positionFalloff.w);
    float _1738 = fast::clamp(fma(-_1733, _1733, 1.0), 0.0, 1.0);
    float _1757 = fast::clamp(fma(dot(-_1729, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1768 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1738) * half(_1738)) / fast::max(_1724, 9.9999997473787516355514526367188e-05)) * half(_1757)) * half(_1757)), float3(65504.0));
    half3 _1881 = normalize(half3(_767) + half3(_1729));
    half _1823 = clamp(dot(_751, half3(_1729)), half(0.0), half(1.0));
    half _1827 = clamp(dot(_751, _1881), half(0.0), half(1.0));
    half4 _1950 = half4(cross(_751, _1881), half(params.facet_alpha) * _1827) * half(64.0);
    half _1919 = _1823 + _946;
    half _1927 = half(6.283185482025146484375) * max(mix((half(2.0) * _1823) * _946, _1919, half(params.facet_alpha)), half(0.000244140625));
    half _1929 = _1262 / (dot(_1950, _1950) * _1927);
    half _1983 = half(8192.0) * fma(half(-float(_1823)), _946, _1919);
    half _1987 = half(1.0) / (_1091 * _1983);
    out.fragColor = float4(half4(_1685 + min(fma(half3(float3(params.facet_f0)) * min(_1929 * (_1929 * _1927), half(65504.0)), (half3(_1768) * _1823) * _1047, (_1082 * ((((fma(_1987, _1983, half(2.0)) * pow(max(fma(half(-float(_1827)), _1827, half(1.0)), half(0.0)), half(0.5) * (_1987 * _1983))) * half(0.15915493667125701904296875)) * (_1823 * (_1987 * _1332))) * _1052)) * half3(_1768)), half3(float3(65504.0))), half(1.0)));
    return out;
}

