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
    half3 _981 = normalize(half3(in.v_normal));
    float3 _987 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1133 = _981.y;
    half _1138 = _981.z;
    half _1143 = _981.x;
    half3 _1211 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1133)) + (half4(frame.sh[2]).xyz * _1138)) + (half4(frame.sh[3]).xyz * _1143)) + (((((half4(frame.sh[4]).xyz * (_1143 * _1133)) + (half4(frame.sh[5]).xyz * (_1133 * _1138))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1138, _1138, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1143 * _1138))) + (half4(frame.sh[8]).xyz * fma(_1143, _1143, half(-float(_1133 * _1133))))), half3(float3(0.0)));
    half _1261 = max(dot(_981, half3(_987)), half(9.9999997473787516355514526367188e-05));
    half3 _1265 = reflect(-half3(_987), _981);
    float4 _1300 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1261, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1319 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1300).y) - half(1.0)));
    float4 _1326 = facet_environment.sample(facet_environmentSmplr, float3(_1265), level(half(params.facet_perceptualRoughness) * half(4.0)));
    half _1403 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1360 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1261, _1403)), level(0.0));
    half3 _1410 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2432 = half4(_1360);
    half _1373 = _2432.z;
    half _1375 = fma(half(-float(max(_1410.x, max(_1410.y, _1410.z)))), _1373, half(1.0));
    half _1419 = _1403 * _1403;
    half4 _2436 = half4(_1360);
    half _1380 = _2436.w;
    float4 _1431 = facet_environment.sample(facet_environmentSmplr, float3(_1265), level(_1403 * half(4.0)));
    float3 _1468 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1471 = dot(_1468, _1468);
    float3 _1476 = _1468 * rsqrt(fast::max(_1471, 9.9999999392252902907785028219223e-09));
    float _1480 = _1471 * float(frame.punctualLights[0].positionFalloff.w);
    float _1485 = fast::clamp(fma(-_1480, _1480, 1.0), 0.0, 1.0);
    float _1504 = fast::clamp(fma(dot(-_1476, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1515 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1485) * half(_1485)) / fast::max(_1471, 9.9999997473787516355514526367188e-05)) * half(_1504)) * half(_1504)), float3(65504.0));
    float3 _1640 = fast::normalize(_987 + _1476);
    half _1572 = clamp(dot(_981, half3(_1476)), half(0.0), half(1.0));
    half _1576 = clamp(dot(_981, half3(_1640)), half(0.0), half(1.0));
    half _1680 = half(4096.0) * half(params.facet_alpha);
    half4 _1705 = half4(cross(_981, half3(_1640)), half(params.facet_alpha) * _1576) * half(64.0);
    half _1686 = _1680 / dot(_1705, _1705);
    half _1716 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1722 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1726 = sqrt(fma(_1261 * _1261, _1722, _1716));
    half _1750 = half(1.0) - clamp(dot(half3(_1476), half3(_1640)), half(0.0), half(1.0));
    half _1753 = _1750 * _1750;
    half3 _1761 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1794 = half(8192.0) * fma(half(-float(_1572)), _1261, _1572 + _1261);
    half _1798 = half(1.0) / (_1419 * _1794);
    half _1805 = half(2048.0) * _1419;
    half3 _1613 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    half3 _1621 = min(fma(fma((half3(float3(params.facet_f0)) + (_1761 * ((_1753 * _1753) * _1750))) * min(min((_1686 * _1686) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1572, _1726, _1261 * sqrt(fma(_1572 * _1572, _1722, _1716))), half(65504.0)), half(65504.0)), _1319, _1613), (half3(_1515) * _1572) * _1375, (_1410 * ((((fma(_1798, _1794, half(2.0)) * pow(max(fma(half(-float(_1576)), _1576, half(1.0)), half(0.0)), half(0.5) * (_1798 * _1794))) * half(0.15915493667125701904296875)) * (_1572 * (_1798 * _1805))) * _1380)) * half3(_1515)), half3(float3(65504.0)));
    float3 _1869 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1872 = dot(_1869, _1869);
    float3 _1877 = _1869 * rsqrt(fast::max(_1872, 9.9999999392252902907785028219223e-09));
    float _1881 = _1872 * float(frame.punctualLights[1].positionFalloff.w);
    float _1886 = fast::clamp(fma(-_1881, _1881, 1.0), 0.0, 1.0);
    float _1905 = fast::clamp(fma(dot(-_1877, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1916 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1886) * half(_1886)) / fast::max(_1872, 9.9999997473787516355514526367188e-05)) * half(_1905)) * half(_1905)), float3(65504.0));
    float3 _2041 = fast::normalize(_987 + _1877);
    half _1973 = clamp(dot(_981, half3(_1877)), half(0.0), half(1.0));
    half _1977 = clamp(dot(_981, half3(_2041)), half(0.0), half(1.0));
    half4 _2106 = half4(cross(_981, half3(_2041)), half(params.facet_alpha) * _1977) * half(64.0);
    half _2087 = _1680 / dot(_2106, _2106);
    half _2151 = half(1.0) - clamp(dot(half3(_1877), half3(_2041)), half(0.0), half(1.0));
    half _2154 = _2151 * _2151;
    half _2195 = half(8192.0) * fma(half(-float(_1973)), _1261, _1973 + _1261);
    half _2199 = half(1.0) / (_1419 * _2195);
    half3 _2022 = min(fma(fma((half3(float3(params.facet_f0)) + (_1761 * ((_2154 * _2154) * _2151))) * min(min((_2087 * _2087) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1973, _1726, _1261 * sqrt(fma(_1973 * _1973, _1722, _1716))), half(65504.0)), half(65504.0)), _1319, _1613), (half3(_1916) * _1973) * _1375, (_1410 * ((((fma(_2199, _2195, half(2.0)) * pow(max(fma(half(-float(_1977)), _1977, half(1.0)), half(0.0)), half(0.5) * (_2199 * _2195))) * half(0.15915493667125701904296875)) * (_1973 * (_2199 * _1805))) * _1380)) * half3(_1916)), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_1431).xyz, _1410 * _1373, fma(half3(float3(params.facet_diffuseColor)), _1211, half4(_1326).xyz * (mix(half4(_1300).xxx, half4(_1300).yyy, half3(float3(params.facet_f0))) * _1319)) * _1375) + _1621) + _2022, half(1.0)));
    return out;
}

