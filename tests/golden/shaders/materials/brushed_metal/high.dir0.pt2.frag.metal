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
    half3 _1079 = half4(in.v_tangent).xyz;
    half3 _1086 = _1079 - (_937 * dot(_937, _1079));
    half _1088 = _937.z;
    half3 _2204;
    if (float(abs(_1088)) < 0.5)
    {
        _2204 = half3(-_937.y, _937.x, half(0.0));
    }
    else
    {
        _2204 = half3(half(0.0), -_1088, _937.y);
    }
    half3 _1115 = normalize(half3(select(float3(_2204), float3(_1086), bool3(float(dot(_1086, _1086)) > 0.001000000047497451305389404296875))));
    half _963 = max(dot(_937, half3(_943)), half(9.9999997473787516355514526367188e-05));
    half3 _1128 = cross(_937, _1115);
    half _1179 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half2 _1174 = clamp(half2(half(1.0) + _1179, half(1.0) - _1179) * half(params.facet_alpha), half2(float2(0.007921000011265277862548828125)), half2(float2(1.0)));
    half2 _1134 = half2(float2(1.0)) / _1174;
    half2 _1136 = _1174 * half(128.0);
    half _1142 = half(0.3183098733425140380859375) * (_1134.x * _1134.y);
    half _1158 = length(half3(_1136 * half2(dot(_1115, half3(_943)), dot(_1128, half3(_943))), half(128.0) * _963));
    half3 _2220 = select(_1128, _1115, bool3(float(_1179) >= 0.0));
    half _1408 = dot(_2220, half3(_943));
    half _1415 = min(abs(_1179) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _1420 = fma(half(-float(_1415)), half(1.0) - _963, half(1.0));
    half _1423 = _1415 * _1408;
    float4 _1463 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_963, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1489 = facet_environment.sample(facet_environmentSmplr, float3(((((_937 * _1420) + (_2220 * _1423)) * (half(512.0) * fma(_1420, _963, _1423 * _1408))) - (half3(_943) * (half(256.0) * fma(_1420, _1420, _1423 * _1423))))), level(half(params.facet_perceptualRoughness) * half(4.0)));
    float3 _1534 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1537 = dot(_1534, _1534);
    float3 _1542 = _1534 * rsqrt(fast::max(_1537, 9.9999999392252902907785028219223e-09));
    float _1546 = _1537 * float(frame.punctualLights[0].positionFalloff.w);
    float _1551 = fast::clamp(fma(-_1546, _1546, 1.0), 0.0, 1.0);
    float _1570 = fast::clamp(fma(dot(-_1542, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1680 = fast::normalize(_943 + _1542);
    half _1629 = clamp(dot(_937, half3(_1542)), half(0.0), half(1.0));
    half _1633 = clamp(dot(_937, half3(_1680)), half(0.0), half(1.0));
    half2 _1698 = half2(dot(_1115, half3(_1680)), dot(_1128, half3(_1680))) * _1134;
    half _1706 = half(1.0) / fma(_1633, _1633, dot(_1698, _1698));
    half _1747 = half(1.0) - clamp(dot(half3(_1542), half3(_1680)), half(0.0), half(1.0));
    half _1750 = _1747 * _1747;
    half3 _1758 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1661 = min(((half3(float3(params.facet_f0)) + (_1758 * ((_1750 * _1750) * _1747))) * min(((_1142 * _1706) * _1706) * min(half(64.0) / fma(_1629, _1158, _963 * length(half3(_1136 * half2(dot(_1115, half3(_1542)), dot(_1128, half3(_1542))), half(128.0) * _1629))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1551) * half(_1551)) / fast::max(_1537, 9.9999997473787516355514526367188e-05)) * half(_1570)) * half(_1570)), float3(65504.0))) * _1629), half3(float3(65504.0)));
    float3 _1816 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1819 = dot(_1816, _1816);
    float3 _1824 = _1816 * rsqrt(fast::max(_1819, 9.9999999392252902907785028219223e-09));
    float _1828 = _1819 * float(frame.punctualLights[1].positionFalloff.w);
    float _1833 = fast::clamp(fma(-_1828, _1828, 1.0), 0.0, 1.0);
    float _1852 = fast::clamp(fma(dot(-_1824, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1962 = fast::normalize(_943 + _1824);
    half _1911 = clamp(dot(_937, half3(_1824)), half(0.0), half(1.0));
    half _1915 = clamp(dot(_937, half3(_1962)), half(0.0), half(1.0));
    half2 _1980 = half2(dot(_1115, half3(_1962)), dot(_1128, half3(_1962))) * _1134;
    half _1988 = half(1.0) / fma(_1915, _1915, dot(_1980, _1980));
    half _2029 = half(1.0) - clamp(dot(half3(_1824), half3(_1962)), half(0.0), half(1.0));
    half _2032 = _2029 * _2029;
    half3 _1943 = min(((half3(float3(params.facet_f0)) + (_1758 * ((_2032 * _2032) * _2029))) * min(((_1142 * _1988) * _1988) * min(half(64.0) / fma(_1911, _1158, _963 * length(half3(_1136 * half2(dot(_1115, half3(_1824)), dot(_1128, half3(_1824))), half(128.0) * _1911))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1833) * half(_1833)) / fast::max(_1819, 9.9999997473787516355514526367188e-05)) * half(_1852)) * half(_1852)), float3(65504.0))) * _1911), half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_1489).xyz, mix(half4(_1463).xxx, half4(_1463).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1463).y) - half(1.0)))), _1661) + _1943, half(1.0)));
    return out;
}

