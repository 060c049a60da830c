#include <metal_stdlib>
#include <simd/simd.h>

using namespace metal;

struct MaterialParams
{
    float3 glazeColor;
    packed_float3 clayColor;
    float glazeRoughness;
    float clayRoughness;
    float bandsPerUnit;
    float bandSharpness;
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
    half3 _846 = normalize(half3(in.v_normal));
    float3 _852 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _974 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _1023 = _846.y;
    half _1028 = _846.z;
    half _1033 = _846.x;
    half3 _1101 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1023)) + (half4(frame.sh[2]).xyz * _1028)) + (half4(frame.sh[3]).xyz * _1033)) + (((((half4(frame.sh[4]).xyz * (_1033 * _1023)) + (half4(frame.sh[5]).xyz * (_1023 * _1028))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1028, _1028, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1033 * _1028))) + (half4(frame.sh[8]).xyz * fma(_1033, _1033, half(-float(_1023 * _1023))))), half3(float3(0.0)));
    half3 _1124 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_974))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1199 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _974)), half(0.0), half(1.0));
    half3 _1207 = half3((half(0.1599999964237213134765625) * _1199) * _1199);
    half _1216 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _974)), half(0.08900000154972076416015625), half(1.0));
    half _1159 = max(dot(_846, half3(_852)), half(9.9999997473787516355514526367188e-05));
    float4 _1223 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1159, _1216)), level(0.0));
    half3 _1242 = half3(float3(1.0)) + (_1207 * ((half(1.0) / half4(_1223).y) - half(1.0)));
    float4 _1252 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_852), _846)), level(_1216 * (half(4.0) * (half(2.0) - _1216))));
    float3 _1297 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1300 = dot(_1297, _1297);
    float3 _1305 = _1297 * rsqrt(fast::max(_1300, 9.9999999392252902907785028219223e-09));
    float _1309 = _1300 * float(frame.punctualLights[0].positionFalloff.w);
    float _1314 = fast::clamp(fma(-_1309, _1309, 1.0), 0.0, 1.0);
    float _1333 = fast::clamp(fma(dot(-_1305, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1475 = _1216 * _1216;
    float3 _1487 = fast::normalize(_852 + _1305);
    half _1396 = clamp(dot(_846, half3(_1305)), half(0.0), half(1.0));
    half3 _1527 = cross(_846, half3(_1487));
    half _1530 = clamp(dot(_846, half3(_1487)), half(0.0), half(1.0)) * _1475;
    half _1539 = _1475 / fma(_1530, _1530, dot(_1527, _1527));
    half _1553 = _1475 * _1475;
    half _1559 = fma(half(-float(_1475)), _1475, half(1.0));
    half _1563 = sqrt(fma(_1159 * _1159, _1559, _1553));
    half _1587 = half(1.0) - clamp(dot(half3(_1305), half3(_1487)), half(0.0), half(1.0));
    half _1590 = _1587 * _1587;
    half3 _1598 = half3(float3(1.0)) - _1207;
    half3 _1427 = _1124 * half(0.3183098733425140380859375);
    float3 _1656 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1659 = dot(_1656, _1656);
    float3 _1664 = _1656 * rsqrt(fast::max(_1659, 9.9999999392252902907785028219223e-09));
    float _1668 = _1659 * float(frame.punctualLights[1].positionFalloff.w);
    float _1673 = fast::clamp(fma(-_1668, _1668, 1.0), 0.0, 1.0);
    float _1692 = fast::clamp(fma(dot(-_1664, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1846 = fast::normalize(_852 + _1664);
    half _1755 = clamp(dot(_846, half3(_1664)), half(0.0), half(1.0));
    half3 _1886 = cross(_846, half3(_1846));
    half _1889 = clamp(dot(_846, half3(_1846)), half(0.0), half(1.0)) * _1475;
    half _1898 = _1475 / fma(_1889, _1889, dot(_1886, _1886));
    half _1946 = half(1.0) - clamp(dot(half3(_1664), half3(_1846)), half(0.0), half(1.0));
    half _1949 = _1946 * _1946;
    half3 _1979 = (fma(_1124, _1101, half4(_1252).xyz * (mix(half4(_1223).xxx, half4(_1223).yyy, _1207) * _1242)) + min(fma((_1207 + (_1598 * ((_1590 * _1590) * _1587))) * min(min((_1539 * _1539) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1396, _1563, _1159 * sqrt(fma(_1396 * _1396, _1559, _1553))), half(65504.0)), half(65504.0)), _1242, _1427) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1314) * half(_1314)) / fast::max(_1300, 9.9999997473787516355514526367188e-05)) * half(_1333)) * half(_1333)), float3(65504.0))) * _1396), half3(float3(65504.0)))) + min(fma((_1207 + (_1598 * ((_1949 * _1949) * _1946))) * min(min((_1898 * _1898) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1755, _1563, _1159 * sqrt(fma(_1755 * _1755, _1559, _1553))), half(65504.0)), half(65504.0)), _1242, _1427) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1673) * half(_1673)) / fast::max(_1659, 9.9999997473787516355514526367188e-05)) * half(_1692)) * half(_1692)), float3(65504.0))) * _1755), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1979, half(1.0)));
    return out;
}

