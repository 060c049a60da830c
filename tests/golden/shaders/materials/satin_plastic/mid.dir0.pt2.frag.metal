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
    half _925 = max(dot(_751, half3(_767)), half(9.9999997473787516355514526367188e-05));
    half3 _929 = reflect(-half3(_767), _751);
    float4 _958 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_925, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _977 = facet_environment.sample(facet_environmentSmplr, float3(_929), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1054 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1011 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_925, _1054)), level(0.0));
    half3 _1061 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _1901 = half4(_1011);
    half _1024 = _1901.z;
    half _1026 = fma(half(-float(max(_1061.x, max(_1061.y, _1061.z)))), _1024, half(1.0));
    half _1070 = _1054 * _1054;
    half4 _1905 = half4(_1011);
    half _1031 = _1905.w;
    float4 _1085 = facet_environment.sample(facet_environmentSmplr, float3(_929), level(_1054 * (half(4.0) * (half(2.0) - _1054))));
    float3 _1122 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1125 = dot(_1122, _1122);
    float3 _1130 = _1122 * rsqrt(fast::max(_1125, 9.9999999392252902907785028219223e-09));
    float _1134 = _1125 * float(frame.punctualLights[0].positionFalloff.w);
    float _1139 = fast::clamp(fma(-_1134, _1134, 1.0), 0.0, 1.0);
    float _1158 = fast::clamp(fma(dot(-_1130, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1169 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1139) * half(_1139)) / fast::max(_1125, 9.9999997473787516355514526367188e-05)) * half(_1158)) * half(_1158)), float3(65504.0));
    half3 _1282 = normalize(half3(_767) + half3(_1130));
    half _1224 = clamp(dot(_751, half3(_1130)), half(0.0), half(1.0));
    half _1228 = clamp(dot(_751, _1282), half(0.0), half(1.0));
    half4 _1351 = half4(cross(_751, _1282), half(params.facet_alpha) * _1228) * half(64.0);
    half _1320 = _1224 + _925;
    half _1325 = half(4096.0) * half(params.facet_alpha);
    half _1328 = half(6.283185482025146484375) * max(mix((half(2.0) * _1224) * _925, _1320, half(params.facet_alpha)), half(0.000244140625));
    half _1330 = _1325 / (dot(_1351, _1351) * _1328);
    half _1384 = half(8192.0) * fma(half(-float(_1224)), _925, _1320);
    half _1388 = half(1.0) / (_1070 * _1384);
    half _1395 = half(2048.0) * _1070;
    float3 _1453 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1456 = dot(_1453, _1453);
    float3 _1461 = _1453 * rsqrt(fast::max(_1456, 9.9999999392252902907785028219223e-09));
    float _1465 = _1456 * float(frame.punctualLights[1].positionFalloff.w);
    float _1470 = fast::clamp(fma(-_1465, _1465, 1.0), 0.0, 1.0);
    float _1489 = fast::clamp(fma(dot(-_1461, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1500 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1470) * half(_1470)) / fast::max(_1456, 9.9999997473787516355514526367188e-05)) * half(_1489)) * half(_1489)), float3(65504.0));
    half3 _1613 = normalize(half3(_767) + half3(_1461));
    half _1555 = clamp(dot(_751, half3(_1461)), half(0.0), half(1.0));
    half _1559 = clamp(dot(_751, _1613), half(0.0), half(1.0));
    half4 _1682 = half4(cross(_751, _1613), half(params.facet_alpha) * _1559) * half(64.0);
    half _1651 = _1555 + _925;
    half _1659 = half(6.283185482025146484375) * max(mix((half(2.0) * _1555) * _925, _1651, half(params.facet_alpha)), half(0.000244140625));
    half _1661 = _1325 / (dot(_1682, _1682) * _1659);
    half _1715 = half(8192.0) * fma(half(-float(_1555)), _925, _1651);
    half _1719 = half(1.0) / (_1070 * _1715);
    half3 _1748 = (fma(half4(_1085).xyz, _1061 * _1024, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_977).xyz * mix(half4(_958).xxx, half4(_958).yyy, half3(float3(params.facet_f0)))) * _1026) + min(fma(half3(float3(params.facet_f0)) * min(_1330 * (_1330 * _1328), half(65504.0)), (half3(_1169) * _1224) * _1026, (_1061 * ((((fma(_1388, _1384, half(2.0)) * pow(max(fma(half(-float(_1228)), _1228, half(1.0)), half(0.0)), half(0.5) * (_1388 * _1384))) * half(0.15915493667125701904296875)) * (_1224 * (_1388 * _1395))) * _1031)) * half3(_1169)), half3(float3(65504.0)))) + min(fma(half3(float3(params.facet_f0)) * min(_1661 * (_1661 * _1659), half(65504.0)), (half3(_1500) * _1555) * _1026, (_1061 * ((((fma(_1719, _1715, half(2.0)) * pow(max(fma(half(-float(_1559)), _1559, half(1.0)), half(0.0)), half(0.5) * (_1719 * _1715))) * half(0.15915493667125701904296875)) * (_1555 * (_1719 * _1395))) * _1031)) * half3(_1500)), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1748, half(1.0)));
    return out;
}

