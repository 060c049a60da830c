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
    half3 _790 = normalize(half3(in.v_normal));
    float3 _806 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    half _985 = max(dot(_790, half3(_806)), half(9.9999997473787516355514526367188e-05));
    half3 _989 = reflect(-half3(_806), _790);
    float4 _1018 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_985, half(params.facet_perceptualRoughness))), level(0.0));
    float4 _1037 = facet_environment.sample(facet_environmentSmplr, float3(_989), level(half(params.facet_perceptualRoughness) * (half(4.0) * (half(2.0) - half(params.facet_perceptualRoughness)))));
    half _1114 = clamp(half(params.sheenRoughness), half(0.08900000154972076416015625), half(1.0));
    float4 _1071 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_985, _1114)), level(0.0));
    half3 _1121 = clamp(half3(float3(params.sheen)), half3(float3(0.0)), half3(float3(1.0)));
    half4 _2309 = half4(_1071);
    half _1084 = _2309.z;
    half _1086 = fma(half(-float(max(_1121.x, max(_1121.y, _1121.z)))), _1084, half(1.0));
    half _1130 = _1114 * _1114;
    half4 _2313 = half4(_1071);
    half _1091 = _2313.w;
    float4 _1145 = facet_environment.sample(facet_environmentSmplr, float3(_989), level(_1114 * (half(4.0) * (half(2.0) - _1114))));
    half3 _864 = half4(frame.lightColor).xyz;
    float3 _1259 = fast::normalize(_806 + frame.lightDirection.xyz);
    half _1200 = clamp(dot(_790, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1204 = clamp(dot(_790, half3(_1259)), half(0.0), half(1.0));
    half _1299 = half(4096.0) * half(params.facet_alpha);
    half4 _1324 = half4(cross(_790, half3(_1259)), half(params.facet_alpha) * _1204) * half(64.0);
    half _1305 = _1299 / dot(_1324, _1324);
    half _1337 = _1200 + _985;
    half _1349 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1259)), half(0.0), half(1.0));
    half _1352 = _1349 * _1349;
    half3 _1360 = half3(float3(1.0)) - half3(float3(params.facet_f0));
    half _1393 = half(8192.0) * fma(half(-float(_1200)), _985, _1337);
    half _1397 = half(1.0) / (_1130 * _1393);
    half _1404 = half(2048.0) * _1130;
    half3 _1240 = min(fma((half3(float3(params.facet_f0)) + (_1360 * ((_1352 * _1352) * _1349))) * min(min((_1305 * _1305) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1200) * _985, _1337, half(params.facet_alpha)), half(65504.0)), half(65504.0)), (_864 * _1200) * _1086, (_1121 * ((((fma(_1397, _1393, half(2.0)) * pow(max(fma(half(-float(_1204)), _1204, half(1.0)), half(0.0)), half(0.5) * (_1397 * _1393))) * half(0.15915493667125701904296875)) * (_1200 * (_1397 * _1404))) * _1091)) * _864), half3(float3(65504.0)));
    float3 _1462 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1465 = dot(_1462, _1462);
    float3 _1470 = _1462 * rsqrt(fast::max(_1465, 9.9999999392252902907785028219223e-09));
    float _1474 = _1465 * float(frame.punctualLights[0].positionFalloff.w);
    float _1479 = fast::clamp(fma(-_1474, _1474, 1.0), 0.0, 1.0);
    float _1498 = fast::clamp(fma(dot(-_1470, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1509 = fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1479) * half(_1479)) / fast::max(_1465, 9.9999997473787516355514526367188e-05)) * half(_1498)) * half(_1498)), float3(65504.0));
    float3 _1623 = fast::normalize(_806 + _1470);
    half _1564 = clamp(dot(_790, half3(_1470)), half(0.0), half(1.0));
    half _1568 = clamp(dot(_790, half3(_1623)), half(0.0), half(1.0));
    half4 _1688 = half4(cross(_790, half3(_1623)), half(params.facet_alpha) * _1568) * half(64.0);
    half _1669 = _1299 / dot(_1688, _1688);
    half _1701 = _1564 + _985;
    half _1713 = half(1.0) - clamp(dot(half3(_1470), half3(_1623)), half(0.0), half(1.0));
    half _1716 = _1713 * _1713;
    half _1757 = half(8192.0) * fma(half(-float(_1564)), _985, _1701);
    half _1761 = half(1.0) / (_1130 * _1757);
    half3 _1604 = min(fma((half3(float3(params.facet_f0)) + (_1360 * ((_1716 * _1716) * _1713))) * min(min((_1669 * _1669) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1564) * _985, _1701, half(params.facet_alpha)), half(65504.0)), half(65504.0)), (half3(_1509) * _1564) * _1086, (_1121 * ((((fma(_1761, _1757, half(2.0)) * pow(max(fma(half(-float(_1568)), _1568, half(1.0)), half(0.0)), half(0.5) * (_1761 * _1757))) * half(0.15915493667125701904296875)) * (_1564 * (_1761 * _1404))) * _1091)) * half3(_1509)), half3(float3(65504.0)));
    float3 _1826 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1829 = dot(_1826, _1826);
    float3 _1834 = _1826 * rsqrt(fast::max(_1829, 9.9999999392252902907785028219223e-09));
    float _1838 = _1829 * float(frame.punctualLights[1].positionFalloff.w);
    float _1843 = fast::clamp(fma(-_1838, _1838, 1.0), 0.0, 1.0);
    float _1862 = fast::clamp(fma(dot(-_1834, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1873 = fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1843) * half(_1843)) / fast::max(_1829, 9.9999997473787516355514526367188e-05)) * half(_1862)) * half(_1862)), float3(65504.0));
    float3 _1987 = fast::normalize(_806 + _1834);
    half _1928 = clamp(dot(_790, half3(_1834)), half(0.0), half(1.0));
    half _1932 = clamp(dot(_790, half3(_1987)), half(0.0), half(1.0));
    half4 _2052 = half4(cross(_790, half3(_1987)), half(params.facet_alpha) * _1932) * half(64.0);
    half _2033 = _1299 / dot(_2052, _2052);
    half _2065 = _1928 + _985;
    half _2077 = half(1.0) - clamp(dot(half3(_1834), half3(_1987)), half(0.0), half(1.0));
    half _2080 = _2077 * _2077;
    half _2121 = half(8192.0) * fma(half(-float(_1928)), _985, _2065);
    half _2125 = half(1.0) / (_1130 * _2121);
    half3 _1968 = min(fma((half3(float3(params.facet_f0)) + (_1360 * ((_2080 * _2080) * _2077))) * min(min((_2033 * _2033) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / mix((half(2.0) * _1928) * _985, _2065, half(params.facet_alpha)), half(65504.0)), half(65504.0)), (half3(_1873) * _1928) * _1086, (_1121 * ((((fma(_2125, _2121, half(2.0)) * pow(max(fma(half(-float(_1932)), _1932, half(1.0)), half(0.0)), half(0.5) * (_2125 * _2121))) * half(0.15915493667125701904296875)) * (_1928 * (_2125 * _1404))) * _1091)) * half3(_1873)), half3(float3(65504.0)));
    out.fragColor = float4(half4(((fma(half4(_1145).xyz, _1121 * _1084, fma(half3(float3(params.facet_diffuseColor)), half3(in.v_diffuseLight), half4(_1037).xyz * mix(half4(_1018).xxx, half4(_1018).yyy, half3(float3(params.facet_f0)))) * _1086) + _1240) + _1604) + _1968, half(1.0)));
    return out;
}

