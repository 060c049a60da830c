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
    half3 _848 = normalize(half3(in.v_normal));
    float3 _854 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _976 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _1025 = _848.y;
    half _1030 = _848.z;
    half _1035 = _848.x;
    half3 _1103 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1025)) + (half4(frame.sh[2]).xyz * _1030)) + (half4(frame.sh[3]).xyz * _1035)) + (((((half4(frame.sh[4]).xyz * (_1035 * _1025)) + (half4(frame.sh[5]).xyz * (_1025 * _1030))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1030, _1030, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1035 * _1030))) + (half4(frame.sh[8]).xyz * fma(_1035, _1035, half(-float(_1025 * _1025))))), half3(float3(0.0)));
    half3 _1126 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_976))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1201 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _976)), half(0.0), half(1.0));
    half3 _1209 = half3((half(0.1599999964237213134765625) * _1201) * _1201);
    half _1218 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _976)), half(0.08900000154972076416015625), half(1.0));
    half _1161 = max(dot(_848, half3(_854)), half(9.9999997473787516355514526367188e-05));
    float4 _1225 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1161, _1218)), level(0.0));
    half3 _1244 = half3(float3(1.0)) + (_1209 * ((half(1.0) / half4(_1225).y) - half(1.0)));
    float4 _1256 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_854), _848)), level(_1218 * (half(4.0) * (half(2.0) - _1218))));
    float3 _1301 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1304 = dot(_1301, _1301);
    float3 _1309 = _1301 * rsqrt(fast::max(_1304, 9.9999999392252902907785028219223e-09));
    float _1313 = _1304 * float(frame.punctualLights[0].positionFalloff.w);
    float _1318 = fast::clamp(fma(-_1313, _1313, 1.0), 0.0, 1.0);
    float _1337 = fast::clamp(fma(dot(-_1309, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    half _1479 = _1218 * _1218;
    float3 _1491 = fast::normalize(_854 + _1309);
    half _1400 = clamp(dot(_848, half3(_1309)), half(0.0), half(1.0));
    half3 _1531 = cross(_848, half3(_1491));
    half _1534 = clamp(dot(_848, half3(_1491)), half(0.0), half(1.0)) * _1479;
    half _1543 = _1479 / fma(_1534, _1534, dot(_1531, _1531));
    half _1557 = _1479 * _1479;
    half _1563 = fma(half(-float(_1479)), _1479, half(1.0));
    half _1567 = sqrt(fma(_1161 * _1161, _1563, _1557));
    half _1591 = half(1.0) - clamp(dot(half3(_1309), half3(_1491)), half(0.0), half(1.0));
    half _1594 = _1591 * _1591;
    half3 _1602 = half3(float3(1.0)) - _1209;
    half3 _1431 = _1126 * half(0.3183098733425140380859375);
    float3 _1660 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1663 = dot(_1660, _1660);
    float3 _1668 = _1660 * rsqrt(fast::max(_1663, 9.9999999392252902907785028219223e-09));
    float _1672 = _1663 * float(frame.punctualLights[1].positionFalloff.w);
    float _1677 = fast::clamp(fma(-_1672, _1672, 1.0), 0.0, 1.0);
    float _1696 = fast::clamp(fma(dot(-_1668, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1850 = fast::normalize(_854 + _1668);
    half _1759 = clamp(dot(_848, half3(_1668)), half(0.0), half(1.0));
    half3 _1890 = cross(_848, half3(_1850));
    half _1893 = clamp(dot(_848, half3(_1850)), half(0.0), half(1.0)) * _1479;
    half _1902 = _1479 / fma(_1893, _1893, dot(_1890, _1890));
    half _1950 = half(1.0) - clamp(dot(half3(_1668), half3(_1850)), half(0.0), half(1.0));
    half _1953 = _1950 * _1950;
    half3 _1983 = (fma(_1126, _1103, half4(_1256).xyz * (mix(half4(_1225).xxx, half4(_1225).yyy, _1209) * _1244)) + min(fma((_1209 + (_1602 * ((_1594 * _1594) * _1591))) * min(min((_1543 * _1543) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1400, _1567, _1161 * sqrt(fma(_1400 * _1400, _1563, _1557))), half(65504.0)), half(65504.0)), _1244, _1431) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1318) * half(_1318)) / fast::max(_1304, 9.9999997473787516355514526367188e-05)) * half(_1337)) * half(_1337)), float3(65504.0))) * _1400), half3(float3(65504.0)))) + min(fma((_1209 + (_1602 * ((_1953 * _1953) * _1950))) * min(min((_1902 * _1902) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1759, _1567, _1161 * sqrt(fma(_1759 * _1759, _1563, _1557))), half(65504.0)), half(65504.0)), _1244, _1431) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_1677) * half(_1677)) / fast::max(_1663, 9.9999997473787516355514526367188e-05)) * half(_1696)) * half(_1696)), float3(65504.0))) * _1759), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1983, half(1.0)));
    return out;
}

