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
};

fragment main0_out main0(main0_in in [[stage_in]], constant FrameUniforms& frame [[buffer(0)]], constant MaterialParams& params [[buffer(2)]], texture2d<float> facet_dfgLut [[texture(0)]], texturecube<float> facet_environment [[texture(2)]], sampler facet_dfgLutSmplr [[sampler(0)]], sampler facet_environmentSmplr [[sampler(2)]])
{
    main0_out out = {};
    half3 _966 = normalize(half3(in.v_normal));
    float3 _972 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1118 = _966.y;
    half _1123 = _966.z;
    half _1128 = _966.x;
    half3 _1196 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1118)) + (half4(frame.sh[2]).xyz * _1123)) + (half4(frame.sh[3]).xyz * _1128)) + (((((half4(frame.sh[4]).xyz * (_1128 * _1118)) + (half4(frame.sh[5]).xyz * (_1118 * _1123))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1123, _1123, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1128 * _1123))) + (half4(frame.sh[8]).xyz * fma(_1128, _1128, half(-float(_1118 * _1118))))), half3(float3(0.0)));
    half _1246 = max(dot(_966, half3(_972)), half(9.9999997473787516355514526367188e-05));
    half3 _1250 = reflect(-half3(_972), _966);
    float4 _1285 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1246, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1304 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1285).y) - half(1.0)));
    float4 _1314 = facet_environment.sample(facet_environmentSmplr, float3(_1250), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1391 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1348 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1246, _1391)), level(0.0));
    half3 _1398 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2405 = half4(_1348);
    half _1361 = _2405.z;
    half _1363 = fma(half(-float(max(_1398.x, max(_1398.y, _1398.z)))), _1361, half(1.0));
    half _1407 = _1391 * _1391;
    half4 _2409 = half4(_1348);
    half _1368 = _2409.w;
    float4 _1422 = facet_environment.sample(facet_environmentSmplr, float3(_1250), level(_1391 * (half(4.0) * (half(2.0) - _1391))));
    float3 _1459 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1462 = dot(_1459, _1459);
    float3 _1467 = _1459 * rsqrt(fast::max(_1462, 9.9999999392252902907785028219223e-09));
    float _1471 = _1462 * float(frame.punctualLights[0].positionFalloff.w);
    float _1476 = fast::clamp(fma(-_1471, _1471, 1.0), 0.0, 1.0);
    float _1495 = fast::clamp(fma(dot(-_1467, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1506 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1476) * half(_1476)) / fast::max(_1462, 9.9999997473787516355514526367188e-05)) * half(_1495)) * half(_1495)), float3(65504.0));
    float3 _1631 = fast::normalize(_972 + _1467);
    half _1563 = clamp(dot(_966, half3(_1467)), half(0.0), half(1.0));
    half _1567 = clamp(dot(_966, half3(_1631)), half(0.0), half(1.0));
    half3 _1671 = cross(_966, half3(_1631));
    half _1674 = _1567 * half(params.facet_alpha);
    half _1683 = half(params.facet_alpha) / fma(_1674, _1674, dot(_1671, _1671));
    half _1697 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1703 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1707 = sqrt(fma(_1246 * _1246, _1703, _1697));
    half _1731 = half(1.0) - clamp(dot(half3(_1467), half3(_1631)), half(0.0), half(1.0));
    half _1734 = _1731 * _1731;
    half3 _1742 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1775 = half(8192.0) * fma(half(-float(_1563)), _1246, _1563 + _1246);
    half _1779 = half(1.0) / (_1407 * _1775);
    half _1786 = half(2048.0) * _1407;
    half3 _1604 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    half3 _1612 = min(fma(fma((half3(float3(params.facet_f0)) + (_1742 * ((_1734 * _1734) * _1731))) * min(min((_1683 * _1683) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1563, _1707, _1246 * sqrt(fma(_1563 * _1563, _1703, _1697))), half(65504.0)), half(65504.0)), _1304, _1604), (half3(_1506) * _1563) * _1363, (_1398 * ((((fma(_1779, _1775, half(2.0)) * pow(max(fma(half(-float(_1567)), _1567, half(1.0)), half(0.0)), half(0.5) * (_1779 * _1775))) * half(0.15915493667125701904296875)) * (_1563 * (_1779 * _1786))) * _1368)) * half3(_1506)), half3(float3(65504.0)));
    float3 _1850 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1853 = dot(_1850, _1850);
    float3 _1858 = _1850 * rsqrt(fast::max(_1853, 9.9999999392252902907785028219223e-09));
    float _1862 = _1853 * float(frame.punctualLights[1].positionFalloff.w);
    float _1867 = fast::clamp(fma(-_1862, _1862, 1.0), 0.0, 1.0);
    float _1886 = fast::clamp(fma(dot(-_1858, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1897 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1867) * half(_1867)) / fast::max(_1853, 9.9999997473787516355514526367188e-05)) * half(_1886)) * half(_1886)), float3(65504.0));
    float3 _2022 = fast::normalize(_972 + _1858);
    half _1954 = clamp(dot(_966, half3(_1858)), half(0.0), half(1.0));
    half _1958 = clamp(dot(_966, half3(_2022)), half(0.0), half(1.0));
    half3 _2062 = cross(_966, half3(_2022));
    half _2065 = _1958 * half(params.facet_alpha);
    half _2074 = half(params.facet_alpha) / fma(_2065, _2065, dot(_2062, _2062));
    half _2122 = half(1.0) - clamp(dot(half3(_1858), half3(_2022)), half(0.0), half(1.0));
    half _2125 = _2122 * _2122;
    half _2166 = half(8192.0) * fma(half(-float(_1954)), _1246, _1954 + _1246);
    half _2170 = half(1.0) / (_1407 * _2166);
    half3 _2003 = min(fma(fma((half3(float3(params.facet_f0)) + (_1742 * ((_2125 * _2125) * _2122))) * min(min((_2074 * _2074) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1954, _1707, _1246 * sqrt(fma(_1954 * _1954, _1703, _1697))), half(65504.0)), half(65504.0)), _1304, _1604), (half3(_1897) * _1954) * _1363, (_1398 * ((((fma(_2170, _2166, half(2.0)) * pow(max(fma(half(-float(_1958)), _1958, half(1.0)), half(0.0)), half(0.5) * (_2170 * _2166))) * half(0.15915493667125701904296875)) * (_1954 * (_2170 * _1786))) * _1368)) * half3(_1897)), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_1422).xyz, _1398 * _1361, fma(half3(float3(params.facet_diffuseColor)), _1196, half4(_1314).xyz * (mix(half4(_1285).xxx, half4(_1285).yyy, half3(float3(params.facet_f0))) * _1304)) * _1363) + _1612) + _2003, half(1.0)));
    return out;
}

