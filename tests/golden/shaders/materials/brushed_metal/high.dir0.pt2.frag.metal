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
    half3 _941 = normalize(half3(in.v_normal));
    float3 _947 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half3 _1082 = half4(in.v_tangent).xyz;
    half3 _1089 = _1082 - (_941 * dot(_941, _1082));
    half _1091 = _941.z;
    half3 _2210;
    if (float(abs(_1091)) < 0.5)
    {
        _2210 = half3(-_941.y, _941.x, half(0.0));
    }
    else
    {
        _2210 = half3(half(0.0), -_1091, _941.y);
    }
    half3 _1118 = normalize(half3(select(float3(_2210), float3(_1089), bool3(float(dot(_1089, _1089)) > 0.001000000047497451305389404296875))));
    half _967 = max(dot(_941, half3(_947)), half(9.9999997473787516355514526367188e-05));
    half3 _1131 = cross(_941, _1118);
    half _1182 = clamp(half(params.anisotropy), half(-1.0), half(1.0));
    half2 _1177 = clamp(half2(half(1.0) + _1182, half(1.0) - _1182) * half(params.facet_alpha), half2(float2(0.007921000011265277862548828125)), half2(float2(1.0)));
    half2 _1137 = half2(float2(1.0)) / _1177;
    half2 _1139 = _1177 * half(128.0);
    half _1145 = half(0.3183098733425140380859375) * (_1137.x * _1137.y);
    half _1161 = length(half3(_1139 * half2(dot(_1118, half3(_947)), dot(_1131, half3(_947))), half(128.0) * _967));
    half3 _2226 = select(_1131, _1118, bool3(float(_1182) >= 0.0));
    half _1411 = dot(_2226, half3(_947));
    half _1418 = min(abs(_1182) * clamp(half(5.0) * half(params.facet_perceptualRoughness), half(0.0), half(1.0)), half(0.9921875));
    half _1423 = fma(half(-float(_1418)), half(1.0) - _967, half(1.0));
    half _1426 = _1418 * _1411;
    float4 _1466 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_967, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1495 = facet_environment.sample(facet_environmentSmplr, float3(((((_941 * _1423) + (_2226 * _1426)) * (half(512.0) * fma(_1423, _967, _1426 * _1411))) - (half3(_947) * (half(256.0) * fma(_1423, _1423, _1426 * _1426))))), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float3 _1540 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1543 = dot(_1540, _1540);
    float3 _1548 = _1540 * rsqrt(fast::max(_1543, 9.9999999392252902907785028219223e-09));
    float _1552 = _1543 * float(frame.punctualLights[0].positionFalloff.w);
    float _1557 = fast::clamp(fma(-_1552, _1552, 1.0), 0.0, 1.0);
    float _1576 = fast::clamp(fma(dot(-_1548, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1686 = fast::normalize(_947 + _1548);
    half _1635 = clamp(dot(_941, half3(_1548)), half(0.0), half(1.0));
    half _1639 = clamp(dot(_941, half3(_1686)), half(0.0), half(1.0));
    half2 _1704 = half2(dot(_1118, half3(_1686)), dot(_1131, half3(_1686))) * _1137;
    half _1712 = half(1.0) / fma(_1639, _1639, dot(_1704, _1704));
    half _1753 = half(1.0) - clamp(dot(half3(_1548), half3(_1686)), half(0.0), half(1.0));
    half _1756 = _1753 * _1753;
    half3 _1764 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1667 = min(((half3(float3(params.facet_f0)) + (_1764 * ((_1756 * _1756) * _1753))) * min(((_1145 * _1712) * _1712) * min(half(64.0) / fma(_1635, _1161, _967 * length(half3(_1139 * half2(dot(_1118, half3(_1548)), dot(_1131, half3(_1548))), half(128.0) * _1635))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1557) * half(_1557)) / fast::max(_1543, 9.9999997473787516355514526367188e-05)) * half(_1576)) * half(_1576)), float3(65504.0))) * _1635), half3(float3(65504.0)));
    float3 _1822 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1825 = dot(_1822, _1822);
    float3 _1830 = _1822 * rsqrt(fast::max(_1825, 9.9999999392252902907785028219223e-09));
    float _1834 = _1825 * float(frame.punctualLights[1].positionFalloff.w);
    float _1839 = fast::clamp(fma(-_1834, _1834, 1.0), 0.0, 1.0);
    float _1858 = fast::clamp(fma(dot(-_1830, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1968 = fast::normalize(_947 + _1830);
    half _1917 = clamp(dot(_941, half3(_1830)), half(0.0), half(1.0));
    half _1921 = clamp(dot(_941, half3(_1968)), half(0.0), half(1.0));
    half2 _1986 = half2(dot(_1118, half3(_1968)), dot(_1131, half3(_1968))) * _1137;
    half _1994 = half(1.0) / fma(_1921, _1921, dot(_1986, _1986));
    half _2035 = half(1.0) - clamp(dot(half3(_1830), half3(_1968)), half(0.0), half(1.0));
    half _2038 = _2035 * _2035;
    half3 _1949 = min(((half3(float3(params.facet_f0)) + (_1764 * ((_2038 * _2038) * _2035))) * min(((_1145 * _1994) * _1994) * min(half(64.0) / fma(_1917, _1161, _967 * length(half3(_1139 * half2(dot(_1118, half3(_1830)), dot(_1131, half3(_1830))), half(128.0) * _1917))), half(65504.0)), half(65504.0))) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1839) * half(_1839)) / fast::max(_1825, 9.9999997473787516355514526367188e-05)) * half(_1858)) * half(_1858)), float3(65504.0))) * _1917), half3(float3(65504.0)));
    out.fragColor = float4(half4(fma(half4(_1495).xyz, mix(half4(_1466).xxx, half4(_1466).yyy, half3(float3(params.facet_f0))) * (half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1466).y) - half(1.0)))), _1667) + _1949, half(1.0)));
    return out;
}

