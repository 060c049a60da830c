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
    half3 _759 = normalize(half3(in.v_normal));
    float3 _775 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _956 = max(dot(_759, half3(_775)), half(9.9999997473787516355514526367188e-05));
    half3 _960 = reflect(-half3(_775), _759);
    float4 _995 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_956, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1014 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_995).y) - half(1.0)));
    float4 _1024 = facet_environment.sample(facet_environmentSmplr, float3(_960), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1101 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1058 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_956, _1101)), level(0.0));
    half3 _1108 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2179 = half4(_1058);
    half _1071 = _2179.z;
    half _1073 = fma(half(-float(max(_1108.x, max(_1108.y, _1108.z)))), _1071, half(1.0));
    half _1117 = _1101 * _1101;
    half4 _2183 = half4(_1058);
    half _1078 = _2183.w;
    float4 _1132 = facet_environment.sample(facet_environmentSmplr, float3(_960), level(_1101 * (half(4.0) * (half(2.0) - _1101))));
    half3 _821 = half4(frame.lightDirection).xyz;
    half3 _833 = half4(frame.lightColor).xyz;
    half3 _1248 = normalize(half3(_775) + _821);
    half _1187 = clamp(dot(_759, _821), half(0.0), half(1.0));
    half _1191 = clamp(dot(_759, _1248), half(0.0), half(1.0));
    half3 _1275 = cross(_759, _1248);
    half _1278 = _1191 * half(params.facet_alpha);
    half _1292 = _1187 + _956;
    half _1295 = max(mix((half(2.0) * _1187) * _956, _1292, half(params.facet_alpha)), half(0.000244140625));
    half _1297 = half(1024.0) * half(params.facet_alpha);
    half _1302 = _1297 / (fma(_1278, _1278, dot(_1275, _1275)) * (half(6433.98193359375) * _1295));
    half _1339 = half(8192.0) * fma(half(-float(_1187)), _956, _1292);
    half _1343 = half(1.0) / (_1117 * _1339);
    half _1350 = half(2048.0) * _1117;
    float3 _1408 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1411 = dot(_1408, _1408);
    float3 _1416 = _1408 * rsqrt(fast::max(_1411, 9.9999999392252902907785028219223e-09));
    float _1420 = _1411 * float(frame.punctualLights[0].positionFalloff.w);
    float _1425 = fast::clamp(fma(-_1420, _1420, 1.0), 0.0, 1.0);
    float _1444 = fast::clamp(fma(dot(-_1416, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1455 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1425) * half(_1425)) / fast::max(_1411, 9.9999997473787516355514526367188e-05)) * half(_1444)) * half(_1444)), float3(65504.0));
    half3 _1571 = normalize(half3(_775) + half3(_1416));
    half _1510 = clamp(dot(_759, half3(_1416)), half(0.0), half(1.0));
    half _1514 = clamp(dot(_759, _1571), half(0.0), half(1.0));
    half3 _1598 = cross(_759, _1571);
    half _1601 = _1514 * half(params.facet_alpha);
    half _1615 = _1510 + _956;
    half _1618 = max(mix((half(2.0) * _1510) * _956, _1615, half(params.facet_alpha)), half(0.000244140625));
    half _1625 = _1297 / (fma(_1601, _1601, dot(_1598, _1598)) * (half(6433.98193359375) * _1618));
    half _1662 = half(8192.0) * fma(half(-float(_1510)), _956, _1615);
    half _1666 = half(1.0) / (_1117 * _1662);
    half3 _1695 = (fma(half4(_1132).xyz, _1108 * _1071, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1024).xyz * (mix(half4(_995).xxx, half4(_995).yyy, half3(float3(params.facet_f0))) * _1014)) * _1073) + min(fma((half3(float3(params.facet_f0)) * min(_1302 * (_1302 * (half(6.283185482025146484375) * _1295)), half(65504.0))) * _1014, (_833 * _1187) * _1073, (_1108 * ((((fma(_1343, _1339, half(2.0)) * pow(max(fma(half(-float(_1191)), _1191, half(1.0)), half(0.0)), half(0.5) * (_1343 * _1339))) * half(0.15915493667125701904296875)) * (_1187 * (_1343 * _1350))) * _1078)) * _833), half3(float3(65504.0)))) + min(fma((half3(float3(params.facet_f0)) * min(_1625 * (_1625 * (half(6.283185482025146484375) * _1618)), half(65504.0))) * _1014, (half3(_1455) * _1510) * _1073, (_1108 * ((((fma(_1666, _1662, half(2.0)) * pow(max(fma(half(-float(_1514)), _1514, half(1.0)), half(0.0)), half(0.5) * (_1666 * _1662))) * half(0.15915493667125701904296875)) * (_1510 * (_1666 * _1350))) * _1078)) * half3(_1455)), half3(float3(65504.0)));
    float3 _1731 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1734 = dot(_1731, _1731);
    float3 _1739 = _1731 * rsqrt(fast::max(_1734, 9.9999999392252902907785028219223e-09));
    float _1743 = _1734 * float(frame.punctualLights[1].positionFalloff.w);
    float _1748 = fast::clamp(fma(-_1743, _1743, 1.0), 0.0, 1.0);
    float _1767 = fast::clamp(fma(dot(-_1739, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1778 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1748) * half(_1748)) / fast::max(_1734, 9.9999997473787516355514526367188e-05)) * half(_1767)) * half(_1767)), float3(65504.0));
    half3 _1894 = normalize(half3(_775) + half3(_1739));
    half _1833 = clamp(dot(_759, half3(_1739)), half(0.0), half(1.0));
    half _1837 = clamp(dot(_759, _1894), half(0.0), half(1.0));
    half3 _1921 = cross(_759, _1894);
    half _1924 = _1837 * half(params.facet_alpha);
    half _1938 = _1833 + _956;
    half _1941 = max(mix((half(2.0) * _1833) * _956, _1938, half(params.facet_alpha)), half(0.000244140625));
    half _1948 = _1297 / (fma(_1924, _1924, dot(_1921, _1921)) * (half(6433.98193359375) * _1941));
    half _1985 = half(8192.0) * fma(half(-float(_1833)), _956, _1938);
    half _1989 = half(1.0) / (_1117 * _1985);
    out.fragColor = float4(half4(_1695 + min(fma((half3(float3(params.facet_f0)) * min(_1948 * (_1948 * (half(6.283185482025146484375) * _1941)), half(65504.0))) * _1014, (half3(_1778) * _1833) * _1073, (_1108 * ((((fma(_1989, _1985, half(2.0)) * pow(max(fma(half(-float(_1837)), _1837, half(1.0)), half(0.0)), half(0.5) * (_1989 * _1985))) * half(0.15915493667125701904296875)) * (_1833 * (_1989 * _1350))) * _1078)) * half3(_1778)), half3(float3(65504.0))), half(1.0)));
    return out;
}

