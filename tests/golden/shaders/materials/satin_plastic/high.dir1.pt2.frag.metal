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
    half3 _1010 = normalize(half3(in.v_normal));
    float3 _1016 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1183 = _1010.y;
    half _1188 = _1010.z;
    half _1193 = _1010.x;
    half3 _1261 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1183)) + (half4(frame.sh[2]).xyz * _1188)) + (half4(frame.sh[3]).xyz * _1193)) + (((((half4(frame.sh[4]).xyz * (_1193 * _1183)) + (half4(frame.sh[5]).xyz * (_1183 * _1188))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1188, _1188, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1193 * _1188))) + (half4(frame.sh[8]).xyz * fma(_1193, _1193, half(-float(_1183 * _1183))))), half3(float3(0.0)));
    half _1311 = max(dot(_1010, half3(_1016)), half(9.9999997473787516355514526367188e-05));
    half3 _1315 = reflect(-half3(_1016), _1010);
    float4 _1350 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1311, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1369 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1350).y) - half(1.0)));
    float4 _1376 = facet_environment.sample(facet_environmentSmplr, float3(_1315), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1449 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1409 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1311, _1449)), level(0.0));
    half3 _1456 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _3003 = half4(_1409);
    half _1422 = _3003.z;
    half _1424 = fma(half(-float(max(_1456.x, max(_1456.y, _1456.z)))), _1422, half(1.0));
    half4 _3007 = half4(_1409);
    half _1426 = _3007.w;
    float4 _1463 = facet_environment.sample(facet_environmentSmplr, float3(_1315), level(_1449 * half(4.0)));
    half3 _1071 = half4(frame.lightColor).xyz;
    float3 _1603 = fast::normalize(_1016 + frame.lightDirection.xyz);
    half _1544 = clamp(dot(_1010, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1548 = clamp(dot(_1010, half3(_1603)), half(0.0), half(1.0));
    half3 _1643 = cross(_1010, half3(_1603));
    half _1646 = _1548 * half(params.facet_alpha);
    half _1655 = half(params.facet_alpha) / fma(_1646, _1646, dot(_1643, _1643));
    half _1669 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1675 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1679 = sqrt(fma(_1311 * _1311, _1675, _1669));
    half _1703 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1603)), half(0.0), half(1.0));
    half _1706 = _1703 * _1703;
    half3 _1714 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half3 _1578 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    half _1786 = _1449 * _1449;
    half _1806 = half(8192.0) * fma(half(-float(_1544)), _1311, _1544 + _1311);
    half _1810 = half(1.0) / (_1786 * _1806);
    half _1817 = half(2048.0) * _1786;
    half3 _1851 = fma(half4(_1463).xyz, _1456 * _1422, fma(half3(float3(params.facet_diffuseColor)), _1261, half4(_1376).xyz * (mix(half4(_1350).xxx, half4(_1350).yyy, half3(float3(params.facet_f0))) * _1369)) * _1424) + (min(fma((half3(float3(params.facet_f0)) + (_1714 * ((_1706 * _1706) * _1703))) * min(min((_1655 * _1655) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1544, _1679, _1311 * sqrt(fma(_1544 * _1544, _1675, _1669))), half(65504.0)), half(65504.0)), _1369, _1578) * ((_1071 * _1544) * _1424), half3(float3(65504.0))) + min((_1456 * ((((fma(_1810, _1806, half(2.0)) * pow(max(fma(half(-float(_1548)), _1548, half(1.0)), half(0.0)), half(0.5) * (_1810 * _1806))) * half(0.15915493667125701904296875)) * (_1544 * (_1810 * _1817))) * _1426)) * _1071, half3(float3(65504.0))));
    float3 _1887 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1890 = dot(_1887, _1887);
    float3 _1895 = _1887 * rsqrt(fast::max(_1890, 9.9999999392252902907785028219223e-09));
    float _1899 = _1890 * float(frame.punctualLights[0].positionFalloff.w);
    float _1904 = fast::clamp(fma(-_1899, _1899, 1.0), 0.0, 1.0);
    float _1923 = fast::clamp(fma(dot(-_1895, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1934 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1904) * half(_1904)) / fast::max(_1890, 9.9999997473787516355514526367188e-05)) * half(_1923)) * half(_1923)), float3(65504.0));
    float3 _2074 = fast::normalize(_1016 + _1895);
    half _2015 = clamp(dot(_1010, half3(_1895)), half(0.0), half(1.0));
    half _2019 = clamp(dot(_1010, half3(_2074)), half(0.0), half(1.0));
    half3 _2114 = cross(_1010, half3(_2074));
    half _2117 = _2019 * half(params.facet_alpha);
    half _2126 = half(params.facet_alpha) / fma(_2117, _2117, dot(_2114, _2114));
    half _2174 = half(1.0) - clamp(dot(half3(_1895), half3(_2074)), half(0.0), half(1.0));
    half _2177 = _2174 * _2174;
    half _2277 = half(8192.0) * fma(half(-float(_2015)), _1311, _2015 + _1311);
    half _2281 = half(1.0) / (_1786 * _2277);
    half3 _2322 = _1851 + (min(fma((half3(float3(params.facet_f0)) + (_1714 * ((_2177 * _2177) * _2174))) * min(min((_2126 * _2126) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2015, _1679, _1311 * sqrt(fma(_2015 * _2015, _1675, _1669))), half(65504.0)), half(65504.0)), _1369, _1578) * ((half3(_1934) * _2015) * _1424), half3(float3(65504.0))) + min((_1456 * ((((fma(_2281, _2277, half(2.0)) * pow(max(fma(half(-float(_2019)), _2019, half(1.0)), half(0.0)), half(0.5) * (_2281 * _2277))) * half(0.15915493667125701904296875)) * (_2015 * (_2281 * _1817))) * _1426)) * half3(_1934), half3(float3(65504.0))));
    float3 _2358 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _2361 = dot(_2358, _2358);
    float3 _2366 = _2358 * rsqrt(fast::max(_2361, 9.9999999392252902907785028219223e-09));
    float _2370 = _2361 * float(frame.punctualLights[1].positionFalloff.w);
    float _2375 = fast::clamp(fma(-_2370, _2370, 1.0), 0.0, 1.0);
    float _2394 = fast::clamp(fma(dot(-_2366, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2405 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2375) * half(_2375)) / fast::max(_2361, 9.9999997473787516355514526367188e-05)) * half(_2394)) * half(_2394)), float3(65504.0));
    float3 _2545 = fast::normalize(_1016 + _2366);
    half _2486 = clamp(dot(_1010, half3(_2366)), half(0.0), half(1.0));
    half _2490 = clamp(dot(_1010, half3(_2545)), half(0.0), half(1.0));
    half3 _2585 = cross(_1010, half3(_2545));
    half _2588 = _2490 * half(params.facet_alpha);
    half _2597 = half(params.facet_alpha) / fma(_2588, _2588, dot(_2585, _2585));
    half _2645 = half(1.0) - clamp(dot(half3(_2366), half3(_2545)), half(0.0), half(1.0));
    half _2648 = _2645 * _2645;
    half _2748 = half(8192.0) * fma(half(-float(_2486)), _1311, _2486 + _1311);
    half _2752 = half(1.0) / (_1786 * _2748);
    half3 _2793 = _2322 + (min(fma((half3(float3(params.facet_f0)) + (_1714 * ((_2648 * _2648) * _2645))) * min(min((_2597 * _2597) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2486, _1679, _1311 * sqrt(fma(_2486 * _2486, _1675, _1669))), half(65504.0)), half(65504.0)), _1369, _1578) * ((half3(_2405) * _2486) * _1424), half3(float3(65504.0))) + min((_1456 * ((((fma(_2752, _2748, half(2.0)) * pow(max(fma(half(-float(_2490)), _2490, half(1.0)), half(0.0)), half(0.5) * (_2752 * _2748))) * half(0.15915493667125701904296875)) * (_2486 * (_2752 * _1817))) * _1426)) * half3(_2405), half3(float3(65504.0))));
    out.fragColor = float4(half4(_2793, half(1.0)));
    return out;
}

