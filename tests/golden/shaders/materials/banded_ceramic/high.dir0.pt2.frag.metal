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
    float _973 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _1022 = _842.y;
    half _1027 = _842.z;
    half _1032 = _842.x;
    half3 _1100 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1022)) + (half4(frame.sh[2]).xyz * _1027)) + (half4(frame.sh[3]).xyz * _1032)) + (((((half4(frame.sh[4]).xyz * (_1032 * _1022)) + (half4(frame.sh[5]).xyz * (_1022 * _1027))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1027, _1027, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1032 * _1027))) + (half4(frame.sh[8]).xyz * fma(_1032, _1032, half(-float(_1022 * _1022))))), half3(float3(0.0)));
    half3 _1123 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_973))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1198 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _973)), half(0.0), half(1.0));
    half3 _1206 = half3((half(0.1599999964237213134765625) * _1198) * _1198);
    half _1215 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _973)), half(0.08900000154972076416015625), half(1.0));
    half _1158 = max(dot(_842, half3(_848)), half(9.9999997473787516355514526367188e-05));
    float4 _1222 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1158, _1215)), level(0.0));
    half3 _1241 = half3(float3(1.0)) + (_1206 * ((half(1.0) / half4(_1222).y) - half(1.0)));
    float4 _1248 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_848), _842)), level(_1215 * half(4.0)));
    float3 _1293 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1296 = dot(_1293, _1293);
    float3 _1301 = _1293 * rsqrt(fast::max(_1296, 9.9999999392252902907785028219223e-09));
    float _1305 = _1296 * float(frame.punctualLights[0].positionFalloff.w);
    float _1310 = fast::clamp(fma(-_1305, _1305, 1.0), 0.0, 1.0);
    float _1329 = fast::clamp(fma(dot(-_1301, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1471 = _1215 * _1215;
    float3 _1483 = fast::normalize(_848 + _1301);
    half _1392 = clamp(dot(_842, half3(_1301)), half(0.0), half(1.0));
    half3 _1523 = cross(_842, half3(_1483));
    half _1526 = clamp(dot(_842, half3(_1483)), half(0.0), half(1.0)) * _1471;
    half _1535 = _1471 / fma(_1526, _1526, dot(_1523, _1523));
    half _1549 = _1471 * _1471;
    half _1555 = fma(half(-float(_1471)), _1471, half(1.0));
    half _1559 = sqrt(fma(_1158 * _1158, _1555, _1549));
    half _1583 = half(1.0) - clamp(dot(half3(_1301), half3(_1483)), half(0.0), half(1.0));
    half _1586 = _1583 * _1583;
    half3 _1594 = half3(float3(1.0)) - _1206;
    half3 _1423 = _1123 * half(0.3183098733425140380859375);
    float3 _1652 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1655 = dot(_1652, _1652);
    float3 _1660 = _1652 * rsqrt(fast::max(_1655, 9.9999999392252902907785028219223e-09));
    float _1664 = _1655 * float(frame.punctualLights[1].positionFalloff.w);
    float _1669 = fast::clamp(fma(-_1664, _1664, 1.0), 0.0, 1.0);
    float _1688 = fast::clamp(fma(dot(-_1660, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1842 = fast::normalize(_848 + _1660);
    half _1751 = clamp(dot(_842, half3(_1660)), half(0.0), half(1.0));
    half3 _1882 = cross(_842, half3(_1842));
    half _1885 = clamp(dot(_842, half3(_1842)), half(0.0), half(1.0)) * _1471;
    half _1894 = _1471 / fma(_1885, _1885, dot(_1882, _1882));
    half _1942 = half(1.0) - clamp(dot(half3(_1660), half3(_1842)), half(0.0), half(1.0));
    half _1945 = _1942 * _1942;
    half3 _1975 = (fma(_1123, _1100, half4(_1248).xyz * (mix(half4(_1222).xxx, half4(_1222).yyy, _1206) * _1241)) + min(fma((_1206 + (_1594 * ((_1586 * _1586) * _1583))) * min(min((_1535 * _1535) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1392, _1559, _1158 * sqrt(fma(_1392 * _1392, _1555, _1549))), half(65504.0)), half(65504.0)), _1241, _1423) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1310) * half(_1310)) / fast::max(_1296, 9.9999997473787516355514526367188e-05)) * half(_1329)) * half(_1329)), float3(65504.0))) * _1392), half3(float3(65504.0)))) + min(fma((_1206 + (_1594 * ((_1945 * _1945) * _1942))) * min(min((_1894 * _1894) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1751, _1559, _1158 * sqrt(fma(_1751 * _1751, _1555, _1549))), half(65504.0)), half(65504.0)), _1241, _1423) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1669) * half(_1669)) / fast::max(_1655, 9.9999997473787516355514526367188e-05)) * half(_1688)) * half(_1688)), float3(65504.0))) * _1751), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1975, half(1.0)));
    return out;
}

