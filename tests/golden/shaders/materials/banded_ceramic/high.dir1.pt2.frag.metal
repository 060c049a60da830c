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
    float _995 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _1044 = _846.y;
    half _1049 = _846.z;
    half _1054 = _846.x;
    half3 _1122 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1044)) + (half4(frame.sh[2]).xyz * _1049)) + (half4(frame.sh[3]).xyz * _1054)) + (((((half4(frame.sh[4]).xyz * (_1054 * _1044)) + (half4(frame.sh[5]).xyz * (_1044 * _1049))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1049, _1049, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1054 * _1049))) + (half4(frame.sh[8]).xyz * fma(_1054, _1054, half(-float(_1044 * _1044))))), half3(float3(0.0)));
    half3 _1145 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_995))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1220 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _995)), half(0.0), half(1.0));
    half3 _1228 = half3((half(0.1599999964237213134765625) * _1220) * _1220);
    half _1237 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _995)), half(0.08900000154972076416015625), half(1.0));
    half _1180 = max(dot(_846, half3(_852)), half(9.9999997473787516355514526367188e-05));
    float4 _1244 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1180, _1237)), level(0.0));
    half3 _1263 = half3(float3(1.0)) + (_1228 * ((half(1.0) / half4(_1244).y) - half(1.0)));
    float4 _1273 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_852), _846)), level(_1237 * (half(4.0) * (half(2.0) - _1237))));
    half _1412 = _1237 * _1237;
    float3 _1424 = fast::normalize(_852 + frame.lightDirection.xyz);
    half _1333 = clamp(dot(_846, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1464 = cross(_846, half3(_1424));
    half _1467 = clamp(dot(_846, half3(_1424)), half(0.0), half(1.0)) * _1412;
    half _1476 = _1412 / fma(_1467, _1467, dot(_1464, _1464));
    half _1490 = _1412 * _1412;
    half _1496 = fma(half(-float(_1412)), _1412, half(1.0));
    half _1500 = sqrt(fma(_1180 * _1180, _1496, _1490));
    half _1524 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1424)), half(0.0), half(1.0));
    half _1527 = _1524 * _1524;
    half3 _1535 = half3(float3(1.0)) - _1228;
    half3 _1364 = _1145 * half(0.3183098733425140380859375);
    float3 _1593 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1596 = dot(_1593, _1593);
    float3 _1601 = _1593 * rsqrt(fast::max(_1596, 9.9999999392252902907785028219223e-09));
    float _1605 = _1596 * float(frame.punctualLights[0].positionFalloff.w);
    float _1610 = fast::clamp(fma(-_1605, _1605, 1.0), 0.0, 1.0);
    float _1629 = fast::clamp(fma(dot(-_1601, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1783 = fast::normalize(_852 + _1601);
    half _1692 = clamp(dot(_846, half3(_1601)), half(0.0), half(1.0));
    half3 _1823 = cross(_846, half3(_1783));
    half _1826 = clamp(dot(_846, half3(_1783)), half(0.0), half(1.0)) * _1412;
    half _1835 = _1412 / fma(_1826, _1826, dot(_1823, _1823));
    half _1883 = half(1.0) - clamp(dot(half3(_1601), half3(_1783)), half(0.0), half(1.0));
    half _1886 = _1883 * _1883;
    float3 _1952 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1955 = dot(_1952, _1952);
    float3 _1960 = _1952 * rsqrt(fast::max(_1955, 9.9999999392252902907785028219223e-09));
    float _1964 = _1955 * float(frame.punctualLights[1].positionFalloff.w);
    float _1969 = fast::clamp(fma(-_1964, _1964, 1.0), 0.0, 1.0);
    float _1988 = fast::clamp(fma(dot(-_1960, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2142 = fast::normalize(_852 + _1960);
    half _2051 = clamp(dot(_846, half3(_1960)), half(0.0), half(1.0));
    half3 _2182 = cross(_846, half3(_2142));
    half _2185 = clamp(dot(_846, half3(_2142)), half(0.0), half(1.0)) * _1412;
    half _2194 = _1412 / fma(_2185, _2185, dot(_2182, _2182));
    half _2242 = half(1.0) - clamp(dot(half3(_1960), half3(_2142)), half(0.0), half(1.0));
    half _2245 = _2242 * _2242;
    half3 _2275 = ((fma(_1145, _1122, half4(_1273).xyz * (mix(half4(_1244).xxx, half4(_1244).yyy, _1228) * _1263)) + min(fma((_1228 + (_1535 * ((_1527 * _1527) * _1524))) * min(min((_1476 * _1476) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1333, _1500, _1180 * sqrt(fma(_1333 * _1333, _1496, _1490))), half(65504.0)), half(65504.0)), _1263, _1364) * (half4(frame.lightColor).xyz * _1333), half3(float3(65504.0)))) + min(fma((_1228 + (_1535 * ((_1886 * _1886) * _1883))) * min(min((_1835 * _1835) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1692, _1500, _1180 * sqrt(fma(_1692 * _1692, _1496, _1490))), half(65504.0)), half(65504.0)), _1263, _1364) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1610) * half(_1610)) / fast::max(_1596, 9.9999997473787516355514526367188e-05)) * half(_1629)) * half(_1629)), float3(65504.0))) * _1692), half3(float3(65504.0)))) + min(fma((_1228 + (_1535 * ((_2245 * _2245) * _2242))) * min(min((_2194 * _2194) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2051, _1500, _1180 * sqrt(fma(_2051 * _2051, _1496, _1490))), half(65504.0)), half(65504.0)), _1263, _1364) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1969) * half(_1969)) / fast::max(_1955, 9.9999997473787516355514526367188e-05)) * half(_1988)) * half(_1988)), float3(65504.0))) * _2051), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2275, half(1.0)));
    return out;
}

