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
    half3 _860 = normalize(half3(in.v_normal));
    float3 _866 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _988 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _1037 = _860.y;
    half _1042 = _860.z;
    half _1047 = _860.x;
    half3 _1115 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1037)) + (half4(frame.sh[2]).xyz * _1042)) + (half4(frame.sh[3]).xyz * _1047)) + (((((half4(frame.sh[4]).xyz * (_1047 * _1037)) + (half4(frame.sh[5]).xyz * (_1037 * _1042))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1042, _1042, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1047 * _1042))) + (half4(frame.sh[8]).xyz * fma(_1047, _1047, half(-float(_1037 * _1037))))), half3(float3(0.0)));
    half3 _1138 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_988))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1213 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _988)), half(0.0), half(1.0));
    half3 _1221 = half3((half(0.1599999964237213134765625) * _1213) * _1213);
    half _1230 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _988)), half(0.08900000154972076416015625), half(1.0));
    half _1173 = max(dot(_860, half3(_866)), half(9.9999997473787516355514526367188e-05));
    float4 _1237 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1173, _1230)), level(0.0));
    half3 _1256 = half3(float3(1.0)) + (_1221 * ((half(1.0) / half4(_1237).y) - half(1.0)));
    float4 _1263 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_866), _860)), level(_1230 * half(4.0)));
    float3 _1308 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1311 = dot(_1308, _1308);
    float3 _1316 = _1308 * rsqrt(fast::max(_1311, 9.9999999392252902907785028219223e-09));
    float _1320 = _1311 * float(frame.punctualLights[0].positionFalloff.w);
    float _1325 = fast::clamp(fma(-_1320, _1320, 1.0), 0.0, 1.0);
    float _1344 = fast::clamp(fma(dot(-_1316, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1486 = _1230 * _1230;
    float3 _1498 = fast::normalize(_866 + _1316);
    half _1407 = clamp(dot(_860, half3(_1316)), half(0.0), half(1.0));
    half _1538 = half(4096.0) * _1486;
    half4 _1563 = half4(cross(_860, half3(_1498)), _1486 * clamp(dot(_860, half3(_1498)), half(0.0), half(1.0))) * half(64.0);
    half _1544 = _1538 / dot(_1563, _1563);
    half _1574 = _1486 * _1486;
    half _1580 = fma(half(-float(_1486)), _1486, half(1.0));
    half _1584 = sqrt(fma(_1173 * _1173, _1580, _1574));
    half _1608 = half(1.0) - clamp(dot(half3(_1316), half3(_1498)), half(0.0), half(1.0));
    half _1611 = _1608 * _1608;
    half3 _1619 = half3(float3(1.0)) - _1221;
    half3 _1438 = _1138 * half(0.3183098733425140380859375);
    float3 _1677 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1680 = dot(_1677, _1677);
    float3 _1685 = _1677 * rsqrt(fast::max(_1680, 9.9999999392252902907785028219223e-09));
    float _1689 = _1680 * float(frame.punctualLights[1].positionFalloff.w);
    float _1694 = fast::clamp(fma(-_1689, _1689, 1.0), 0.0, 1.0);
    float _1713 = fast::clamp(fma(dot(-_1685, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1867 = fast::normalize(_866 + _1685);
    half _1776 = clamp(dot(_860, half3(_1685)), half(0.0), half(1.0));
    half4 _1932 = half4(cross(_860, half3(_1867)), _1486 * clamp(dot(_860, half3(_1867)), half(0.0), half(1.0))) * half(64.0);
    half _1913 = _1538 / dot(_1932, _1932);
    half _1977 = half(1.0) - clamp(dot(half3(_1685), half3(_1867)), half(0.0), half(1.0));
    half _1980 = _1977 * _1977;
    half3 _2010 = (fma(_1138, _1115, half4(_1263).xyz * (mix(half4(_1237).xxx, half4(_1237).yyy, _1221) * _1256)) + min(fma((_1221 + (_1619 * ((_1611 * _1611) * _1608))) * min(min((_1544 * _1544) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1407, _1584, _1173 * sqrt(fma(_1407 * _1407, _1580, _1574))), half(65504.0)), half(65504.0)), _1256, _1438) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1325) * half(_1325)) / fast::max(_1311, 9.9999997473787516355514526367188e-05)) * half(_1344)) * half(_1344)), float3(65504.0))) * _1407), half3(float3(65504.0)))) + min(fma((_1221 + (_1619 * ((_1980 * _1980) * _1977))) * min(min((_1913 * _1913) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1776, _1584, _1173 * sqrt(fma(_1776 * _1776, _1580, _1574))), half(65504.0)), half(65504.0)), _1256, _1438) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1694) * half(_1694)) / fast::max(_1680, 9.9999997473787516355514526367188e-05)) * half(_1713)) * half(_1713)), float3(65504.0))) * _1776), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2010, half(1.0)));
    return out;
}

