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
    half3 _842 = normalize(half3(in.v_normal));
    float3 _848 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _970 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _1019 = _842.y;
    half _1024 = _842.z;
    half _1029 = _842.x;
    half3 _1097 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1019)) + (half4(frame.sh[2]).xyz * _1024)) + (half4(frame.sh[3]).xyz * _1029)) + (((((half4(frame.sh[4]).xyz * (_1029 * _1019)) + (half4(frame.sh[5]).xyz * (_1019 * _1024))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1024, _1024, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1029 * _1024))) + (half4(frame.sh[8]).xyz * fma(_1029, _1029, half(-float(_1019 * _1019))))), half3(float3(0.0)));
    half3 _1120 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_970))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1195 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _970)), half(0.0), half(1.0));
    half3 _1203 = half3((half(0.1599999964237213134765625) * _1195) * _1195);
    half _1212 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _970)), half(0.08900000154972076416015625), half(1.0));
    half _1155 = max(dot(_842, half3(_848)), half(9.9999997473787516355514526367188e-05));
    float4 _1219 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1155, _1212)), level(0.0));
    half3 _1238 = half3(float3(1.0)) + (_1203 * ((half(1.0) / half4(_1219).y) - half(1.0)));
    float4 _1245 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_848), _842)), level(_1212 * half(4.0)));
    float3 _1290 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1293 = dot(_1290, _1290);
    float3 _1298 = _1290 * rsqrt(fast::max(_1293, 9.9999999392252902907785028219223e-09));
    float _1302 = _1293 * float(frame.punctualLights[0].positionFalloff.w);
    float _1307 = fast::clamp(fma(-_1302, _1302, 1.0), 0.0, 1.0);
    float _1326 = fast::clamp(fma(dot(-_1298, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1468 = _1212 * _1212;
    float3 _1480 = fast::normalize(_848 + _1298);
    half _1389 = clamp(dot(_842, half3(_1298)), half(0.0), half(1.0));
    half3 _1520 = cross(_842, half3(_1480));
    half _1523 = clamp(dot(_842, half3(_1480)), half(0.0), half(1.0)) * _1468;
    half _1532 = _1468 / fma(_1523, _1523, dot(_1520, _1520));
    half _1546 = _1468 * _1468;
    half _1552 = fma(half(-float(_1468)), _1468, half(1.0));
    half _1556 = sqrt(fma(_1155 * _1155, _1552, _1546));
    half _1580 = half(1.0) - clamp(dot(half3(_1298), half3(_1480)), half(0.0), half(1.0));
    half _1583 = _1580 * _1580;
    half3 _1591 = half3(float3(1.0)) - _1203;
    half3 _1420 = _1120 * half(0.3183098733425140380859375);
    float3 _1649 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1652 = dot(_1649, _1649);
    float3 _1657 = _1649 * rsqrt(fast::max(_1652, 9.9999999392252902907785028219223e-09));
    float _1661 = _1652 * float(frame.punctualLights[1].positionFalloff.w);
    float _1666 = fast::clamp(fma(-_1661, _1661, 1.0), 0.0, 1.0);
    float _1685 = fast::clamp(fma(dot(-_1657, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1839 = fast::normalize(_848 + _1657);
    half _1748 = clamp(dot(_842, half3(_1657)), half(0.0), half(1.0));
    half3 _1879 = cross(_842, half3(_1839));
    half _1882 = clamp(dot(_842, half3(_1839)), half(0.0), half(1.0)) * _1468;
    half _1891 = _1468 / fma(_1882, _1882, dot(_1879, _1879));
    half _1939 = half(1.0) - clamp(dot(half3(_1657), half3(_1839)), half(0.0), half(1.0));
    half _1942 = _1939 * _1939;
    half3 _1972 = (fma(_1120, _1097, half4(_1245).xyz * (mix(half4(_1219).xxx, half4(_1219).yyy, _1203) * _1238)) + min(fma((_1203 + (_1591 * ((_1583 * _1583) * _1580))) * min(min((_1532 * _1532) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1389, _1556, _1155 * sqrt(fma(_1389 * _1389, _1552, _1546))), half(65504.0)), half(65504.0)), _1238, _1420) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1307) * half(_1307)) / fast::max(_1293, 9.9999997473787516355514526367188e-05)) * half(_1326)) * half(_1326)), float3(65504.0))) * _1389), half3(float3(65504.0)))) + min(fma((_1203 + (_1591 * ((_1942 * _1942) * _1939))) * min(min((_1891 * _1891) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1748, _1556, _1155 * sqrt(fma(_1748 * _1748, _1552, _1546))), half(65504.0)), half(65504.0)), _1238, _1420) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1666) * half(_1666)) / fast::max(_1652, 9.9999997473787516355514526367188e-05)) * half(_1685)) * half(_1685)), float3(65504.0))) * _1748), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1972, half(1.0)));
    return out;
}

