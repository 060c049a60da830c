#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    packed_float3 tint;
    float roughness;
    float anisotropy;
    float facet_pad20;
    float facet_pad24;
    float facet_pad28;
    float facet_perceptualRoughness;
    char _m7_pad[12];
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
    float4 v_tangent [[user(locn2)]];
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _937 = normalize(half3(in.v_normal));
    float3 _943 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _1100 = half4(in.v_tangent).xyz;
    half3 _1107 = _1100 - (_937 * dot(_937, _1100));
    half _1109 = _937.z;
    half3 _2427;
    if (float(abs(_1109)) < 0.5)
    {
        _2427 = half3(-_937.y, _937.x, half(0.0));
    }
    else
    {
        _2427 = half3(half(0.0), -_1109, _937.y);
    }
    half3 _1136 = normalize(half3(select(float3(_2427), float3(_1107), bool3(float(dot(_1107, _1107)) > 0.001000000047497451305389404296875))));
    half _963 = max(dot(_937, half3(_943)), half(9.9999997473787516355514526367188e-05));
    half3 _1149 = cross(_937, _1136);
    half _1200 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half2 _1195 = clamp(half2(half(1.0) + _1200, half(1.0) - _1200) * half(params.facet_alpha), half2(float2(0.007921000011265277862548828125)), half2(float2(1.0)));
    half2 _1155 = half2(float2(1.0)) / _1195;
    half2 _1157 = _1195 * half(128.0);
    half _1163 = half(0.3183098733425140380859375) * (_1155.x * _1155.y);
    half _1179 = length(half3(_1157 * half2(dot(_1136, half3(_943)), dot(_1149, half3(_943))), half(128.0) * _963));
    half3 _2443 = select(_1149, _1136, bool3(float(_1200) >= 0.0));
    half _1429 = dot(_2443, half3(_943));
    half _1436 = min(abs(_1200) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _1441 = fma(half(-float(_1436)), half(1.0) - _963, half(1.0));
    half _1444 = _1436 * _1429;
    float4 _1484 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_963, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1510 = facet_environment.sample(facet_environmentSmplr, float3(((((_937 * _1441) + (_2443 * _1444)) * (half(512.0) * fma(_1441, _963, _1444 * _1429))) - (half3(_943) * (half(256.0) * fma(_1441, _1441, _1444 * _1444))))), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1617 = fast::normalize(_943 + frame.lightDirection.xyz);
    half _1566 = clamp(dot(_937, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1570 = clamp(dot(_937, half3(_1617)), half(0.0), half(1.0));
    half2 _1635 = half2(dot(_1136, half3(_1617)), dot(_1149, half3(_1617))) * _1155;
    half _1643 = half(1.0) / fma(_1570, _1570, dot(_1635, _1635));
    half _1684 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1617)), half(0.0), half(1.0));
    half _1687 = _1684 * _1684;
    half3 _1695 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    float3 _1753 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1756 = dot(_1753, _1753);
    float3 _1761 = _1753 * rsqrt(fast::max(_1756, 9.9999999392252902907785028219223e-09));
    float _1765 = _1756 * float(frame.punctualLights[0].positionFalloff.w);
    float _1770 = fast::clamp(fma(-_1765, _1765, 1.0), 0.0, 1.0);
    float _1789 = fast::clamp(fma(dot(-_1761, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1899 = fast::normalize(_943 + _1761);
    half _1848 = clamp(dot(_937, half3(_1761)), half(0.0), half(1.0));
    half _1852 = clamp(dot(_937, half3(_1899)), half(0.0), half(1.0));
    half2 _1917 = half2(dot(_1136, half3(_1899)), dot(_1149, half3(_1899))) * _1155;
    half _1925 = half(1.0) / fma(_1852, _1852, dot(_1917, _1917));
    half _1966 = half(1.0) - clamp(dot(half3(_1761), half3(_1899)), half(0.0), half(1.0));
    half _1969 = _1966 * _1966;
    half3 _1880 = min(((half3(float3(params.facet_f0)) + (_1695 * ((_1969 * _1969) * _1966))) * min(((_1163 * _1925) * _1925) * min(half(64.0) / fma(_1848, _1179, _963 * length(half3(_1157 * half2(dot(_1136, half3(_1761)), dot(_1149, half3(_1761))), half(128.0) * _1848))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1770) * half(_1770)) / fast::max(_1756, 9.9999997473787516355514526367188e-05)) * half(_1789)) * half(_1789)), float3(65504.0))) * _1848), half3(float3(65504.0)));
    half3 _1999 = fma(half4(_1510).xyz, mix(half4(_1484).xxx, half4(_1484).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1484).y) - half(1.0)))), min(((half3(float3(params.facet_f0)) + (_1695 * ((_1687 * _1687) * _1684))) * min(((_1163 * _1643) * _1643) * min(half(64.0) / fma(_1566, _1179, _963 * length(half3(_1157 * half2(dot(_1136, half3(frame.lightDirection.xyz)), dot(_1149, half3(frame.lightDirection.xyz))), half(128.0) * _1566))), half(65504.0)), half(65504.0))) * (half4(frame.lightColor).xyz * _1566), half3(float3(65504.0)))) + _1880;
    float3 _2035 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2038 = dot(_2035, _2035);
    float3 _2043 = _2035 * rsqrt(fast::max(_2038, 9.9999999392252902907785028219223e-09));
    float _2047 = _2038 * float(frame.punctualLights[1].positionFalloff.w);
    float _2052 = fast::clamp(fma(-_2047, _2047, 1.0), 0.0, 1.0);
    float _2071 = fast::clamp(fma(dot(-_2043, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2181 = fast::normalize(_943 + _2043);
    half _2130 = clamp(dot(_937, half3(_2043)), half(0.0), half(1.0));
    half _2134 = clamp(dot(_937, half3(_2181)), half(0.0), half(1.0));
    half2 _2199 = half2(dot(_1136, half3(_2181)), dot(_1149, half3(_2181))) * _1155;
    half _2207 = half(1.0) / fma(_2134, _2134, dot(_2199, _2199));
    half _2248 = half(1.0) - clamp(dot(half3(_2043), half3(_2181)), half(0.0), half(1.0));
    half _2251 = _2248 * _2248;
    half3 _2162 = min(((half3(float3(params.facet_f0)) + (_1695 * ((_2251 * _2251) * _2248))) * min(((_1163 * _2207) * _2207) * min(half(64.0) / fma(_2130, _1179, _963 * length(half3(_1157 * half2(dot(_1136, half3(_2043)), dot(_1149, half3(_2043))), half(128.0) * _2130))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2052) * half(_2052)) / fast::max(_2038, 9.9999997473787516355514526367188e-05)) * half(_2071)) * half(_2071)), float3(65504.0))) * _2130), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1999 + _2162, half(1.0)));
    return out;
}

