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
    packed_float3 facet_sheenColor;
    float facet_sheenLod;
    float facet_sheenRoughness;
    float facet_sheenAlpha;
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
    half3 _783 = normalize(half3(in.v_normal));
    float3 _799 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _979 = max(dot(_783, half3(_799)), half(9.9999997473787516355514526367188e-05));
    half3 _983 = reflect(-half3(_799), _783);
    float4 _1012 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_979, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1031 = facet_environment.sample(facet_environmentSmplr, float3(_983), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    float4 _1063 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_979, half(params.facet_sheenRoughness))), level(0.0));
    half4 _2271 = half4(_1063);
    half _1076 = _2271.z;
    half _1078 = fma(half(-float(max(half3(float3(params.facet_sheenColor)).x, max(half3(float3(params.facet_sheenColor)).y, half3(float3(params.facet_sheenColor)).z)))), _1076, half(1.0));
    half4 _2275 = half4(_1063);
    half _1083 = _2275.w;
    float4 _1092 = facet_environment.sample(facet_environmentSmplr, float3(_983), level(params.facet_sheenLod));
    half3 _857 = half4(frame.lightColor).xyz;
    float3 _1229 = fast::normalize(_799 + frame.lightDirection.xyz);
    half _1170 = clamp(dot(_783, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1174 = clamp(dot(_783, half3(_1229)), half(0.0), half(1.0));
    half _1269 = half(4096.0) * half(params.facet_alpha);
    half4 _1294 = half4(cross(_783, half3(_1229)), half(params.facet_alpha) * _1174) * half(64.0);
    half _1275 = _1269 / dot(_1294, _1294);
    half _1307 = _1170 + _979;
    half _1319 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1229)), half(0.0), half(1.0));
    half _1322 = _1319 * _1319;
    half3 _1330 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1363 = half(8192.0) * fma(half(-float(_1170)), _979, _1307);
    half _1367 = half(1.0) / (half(params.facet_sheenAlpha) * _1363);
    half _1374 = half(2048.0) * half(params.facet_sheenAlpha);
    half3 _1210 = min(fma((half3(float3(params.facet_f0)) + (_1330 * ((_1322 * _1322) * _1319))) * min(min((_1275 * _1275) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1170) * _979, _1307, half(params.facet_alpha)), half(65504.0)), half(65504.0)), (_857 * _1170) * _1078, (half3(float3(params.facet_sheenColor)) * ((((fma(_1367, _1363, half(2.0)) * pow(max(fma(half(-float(_1174)), _1174, half(1.0)), half(0.0)), half(0.5) * (_1367 * _1363))) * half(0.15915493667125701904296875)) * (_1170 * (_1367 * _1374))) * _1083)) * _857), half3(float3(65504.0)));
    float3 _1432 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1435 = dot(_1432, _1432);
    float3 _1440 = _1432 * rsqrt(fast::max(_1435, 9.9999999392252902907785028219223e-09));
    float _1444 = _1435 * float(frame.punctualLights[0].positionFalloff.w);
    float _1449 = fast::clamp(fma(-_1444, _1444, 1.0), 0.0, 1.0);
    float _1468 = fast::clamp(fma(dot(-_1440, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1479 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1449) * half(_1449)) / fast::max(_1435, 9.9999997473787516355514526367188e-05)) * half(_1468)) * half(_1468)), float3(65504.0));
    float3 _1593 = fast::normalize(_799 + _1440);
    half _1534 = clamp(dot(_783, half3(_1440)), half(0.0), half(1.0));
    half _1538 = clamp(dot(_783, half3(_1593)), half(0.0), half(1.0));
    half4 _1658 = half4(cross(_783, half3(_1593)), half(params.facet_alpha) * _1538) * half(64.0);
    half _1639 = _1269 / dot(_1658, _1658);
    half _1671 = _1534 + _979;
    half _1683 = half(1.0) - clamp(dot(half3(_1440), half3(_1593)), half(0.0), half(1.0));
    half _1686 = _1683 * _1683;
    half _1727 = half(8192.0) * fma(half(-float(_1534)), _979, _1671);
    half _1731 = half(1.0) / (half(params.facet_sheenAlpha) * _1727);
    half3 _1574 = min(fma((half3(float3(params.facet_f0)) + (_1330 * ((_1686 * _1686) * _1683))) * min(min((_1639 * _1639) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1534) * _979, _1671, half(params.facet_alpha)), half(65504.0)), half(65504.0)), (half3(_1479) * _1534) * _1078, (half3(float3(params.facet_sheenColor)) * ((((fma(_1731, _1727, half(2.0)) * pow(max(fma(half(-float(_1538)), _1538, half(1.0)), half(0.0)), half(0.5) * (_1731 * _1727))) * half(0.15915493667125701904296875)) * (_1534 * (_1731 * _1374))) * _1083)) * half3(_1479)), half3(float3(65504.0)));
    float3 _1796 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1799 = dot(_1796, _1796);
    float3 _1804 = _1796 * rsqrt(fast::max(_1799, 9.9999999392252902907785028219223e-09));
    float _1808 = _1799 * float(frame.punctualLights[1].positionFalloff.w);
    float _1813 = fast::clamp(fma(-_1808, _1808, 1.0), 0.0, 1.0);
    float _1832 = fast::clamp(fma(dot(-_1804, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1843 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1813) * half(_1813)) / fast::max(_1799, 9.9999997473787516355514526367188e-05)) * half(_1832)) * half(_1832)), float3(65504.0));
    float3 _1957 = fast::normalize(_799 + _1804);
    half _1898 = clamp(dot(_783, half3(_1804)), half(0.0), half(1.0));
    half _1902 = clamp(dot(_783, half3(_1957)), half(0.0), half(1.0));
    half4 _2022 = half4(cross(_783, half3(_1957)), half(params.facet_alpha) * _1902) * half(64.0);
    half _2003 = _1269 / dot(_2022, _2022);
    half _2035 = _1898 + _979;
    half _2047 = half(1.0) - clamp(dot(half3(_1804), half3(_1957)), half(0.0), half(1.0));
    half _2050 = _2047 * _2047;
    half _2091 = half(8192.0) * fma(half(-float(_1898)), _979, _2035);
    half _2095 = half(1.0) / (half(params.facet_sheenAlpha) * _2091);
    half3 _1938 = min(fma((half3(float3(params.facet_f0)) + (_1330 * ((_2050 * _2050) * _2047))) * min(min((_2003 * _2003) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1898) * _979, _2035, half(params.facet_alpha)), half(65504.0)), half(65504.0)), (half3(_1843) * _1898) * _1078, (half3(float3(params.facet_sheenColor)) * ((((fma(_2095, _2091, half(2.0)) * pow(max(fma(half(-float(_1902)), _1902, half(1.0)), half(0.0)), half(0.5) * (_2095 * _2091))) * half(0.15915493667125701904296875)) * (_1898 * (_2095 * _1374))) * _1083)) * half3(_1843)), half3(float3(65504.0)));
    out.fragColor = float4(half4(((fma(half4(_1092).xyz, half3(float3(params.facet_sheenColor)) * _1076, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1031).xyz * mix(half4(_1012).xxx, half4(_1012).yyy, half3(float3(params.facet_f0)))) * _1078) + _1210) + _1574) + _1938, half(1.0)));
    return out;
}

