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
    half3 _984 = normalize(half3(in.v_normal));
    float3 _990 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _1136 = _984.y;
    half _1141 = _984.z;
    half _1146 = _984.x;
    half3 _1214 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1136)) + (half4(frame.sh[2]).xyz * _1141)) + (half4(frame.sh[3]).xyz * _1146)) + (((((half4(frame.sh[4]).xyz * (_1146 * _1136)) + (half4(frame.sh[5]).xyz * (_1136 * _1141))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1141, _1141, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1146 * _1141))) + (half4(frame.sh[8]).xyz * fma(_1146, _1146, half(-float(_1136 * _1136))))), half3(float3(0.0)));
    half _1264 = max(dot(_984, half3(_990)), half(9.9999997473787516355514526367188e-05));
    half3 _1268 = reflect(-half3(_990), _984);
    float4 _1303 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1264, half(params.facet_perceptualRoughness))), level(0.0));
    half3 _1322 = half3(float3(1.0)) + (half3(float3(params.facet_f0)) * ((half(1.0) / half4(_1303).y) - half(1.0)));
    float4 _1332 = facet_environment.sample(facet_environmentSmplr, float3(_1268), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1409 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1366 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1264, _1409)), level(0.0));
    half3 _1416 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2443 = half4(_1366);
    half _1379 = _2443.z;
    half _1381 = fma(half(-float(max(_1416.x, max(_1416.y, _1416.z)))), _1379, half(1.0));
    half _1425 = _1409 * _1409;
    half4 _2447 = half4(_1366);
    half _1386 = _2447.w;
    float4 _1440 = facet_environment.sample(facet_environmentSmplr, float3(_1268), level(_1409 * (half(4.0) * (half(2.0) - _1409))));
    float3 _1477 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1480 = dot(_1477, _1477);
    float3 _1485 = _1477 * rsqrt(fast::max(_1480, 9.9999999392252902907785028219223e-09));
    float _1489 = _1480 * float(frame.punctualLights[0].positionFalloff.w);
    float _1494 = fast::clamp(fma(-_1489, _1489, 1.0), 0.0, 1.0);
    float _1513 = fast::clamp(fma(dot(-_1485, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1524 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1494) * half(_1494)) / fast::max(_1480, 9.9999997473787516355514526367188e-05)) * half(_1513)) * half(_1513)), float3(65504.0));
    float3 _1649 = fast::normalize(_990 + _1485);
    half _1581 = clamp(dot(_984, half3(_1485)), half(0.0), half(1.0));
    half _1585 = clamp(dot(_984, half3(_1649)), half(0.0), half(1.0));
    half _1689 = half(4096.0) * half(params.facet_alpha);
    half4 _1714 = half4(cross(_984, half3(_1649)), half(params.facet_alpha) * _1585) * half(64.0);
    half _1695 = _1689 / dot(_1714, _1714);
    half _1725 = half(params.facet_alpha) * half(params.facet_alpha);
    half _1731 = fma(half(-params.facet_alpha), half(params.facet_alpha), half(1.0));
    half _1735 = sqrt(fma(_1264 * _1264, _1731, _1725));
    half _1759 = half(1.0) - clamp(dot(half3(_1485), half3(_1649)), half(0.0), half(1.0));
    half _1762 = _1759 * _1759;
    half3 _1770 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1803 = half(8192.0) * fma(half(-float(_1581)), _1264, _1581 + _1264);
    half _1807 = half(1.0) / (_1425 * _1803);
    half _1814 = half(2048.0) * _1425;
    half3 _1622 = half3(float3(params.facet_diffuseColor)) * half(0.3183098733425140380859375);
    half3 _1630 = min(fma(fma((half3(float3(params.facet_f0)) + (_1770 * ((_1762 * _1762) * _1759))) * min(min((_1695 * _1695) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1581, _1735, _1264 * sqrt(fma(_1581 * _1581, _1731, _1725))), half(65504.0)), half(65504.0)), _1322, _1622), (half3(_1524) * _1581) * _1381, (_1416 * ((((fma(_1807, _1803, half(2.0)) * pow(max(fma(half(-float(_1585)), _1585, half(1.0)), half(0.0)), half(0.5) * (_1807 * _1803))) * half(0.15915493667125701904296875)) * (_1581 * (_1807 * _1814))) * _1386)) * half3(_1524)), half3(float3(65504.0)));
    float3 _1878 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1881 = dot(_1878, _1878);
    float3 _1886 = _1878 * rsqrt(fast::max(_1881, 9.9999999392252902907785028219223e-09));
    float _1890 = _1881 * float(frame.punctualLights[1].positionFalloff.w);
    float _1895 = fast::clamp(fma(-_1890, _1890, 1.0), 0.0, 1.0);
    float _1914 = fast::clamp(fma(dot(-_1886, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1925 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1895) * half(_1895)) / fast::max(_1881, 9.9999997473787516355514526367188e-05)) * half(_1914)) * half(_1914)), float3(65504.0));
    float3 _2050 = fast::normalize(_990 + _1886);
    half _1982 = clamp(dot(_984, half3(_1886)), half(0.0), half(1.0));
    half _1986 = clamp(dot(_984, half3(_2050)), half(0.0), half(1.0));
    half4 _2115 = half4(cross(_984, half3(_2050)), half(params.facet_alpha) * _1986) * half(64.0);
    half _2096 = _1689 / dot(_2115, _2115);
    half _2160 = half(1.0) - clamp(dot(half3(_1886), half3(_2050)), half(0.0), half(1.0));
    half _2163 = _2160 * _2160;
    half _2204 = half(8192.0) * fma(half(-float(_1982)), _1264, _1982 + _1264);
    half _2208 = half(1.0) / (_1425 * _2204);
    half3 _2031 = min(fma(fma((half3(float3(params.facet_f0)) + (_1770 * ((_2163 * _2163) * _2160))) * min(min((_2096 * _2096) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1982, _1735, _1264 * sqrt(fma(_1982 * _1982, _1731, _1725))), half(65504.0)), half(65504.0)), _1322, _1622), (half3(_1925) * _1982) * _1381, (_1416 * ((((fma(_2208, _2204, half(2.0)) * pow(max(fma(half(-float(_1986)), _1986, half(1.0)), half(0.0)), half(0.5) * (_2208 * _2204))) * half(0.15915493667125701904296875)) * (_1982 * (_2208 * _1814))) * _1386)) * half3(_1925)), half3(float3(65504.0)));
    out.fragColor = float4(half4((fma(half4(_1440).xyz, _1416 * _1379, fma(half3(float3(params.facet_diffuseColor)), _1214, half4(_1332).xyz * (mix(half4(_1303).xxx, half4(_1303).yyy, half3(float3(params.facet_f0))) * _1322)) * _1381) + _1630) + _2031, half(1.0)));
    return out;
}

