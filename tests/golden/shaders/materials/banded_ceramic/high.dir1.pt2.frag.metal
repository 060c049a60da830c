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
    half3 _864 = normalize(half3(in.v_normal));
    float3 _870 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _1013 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _1062 = _864.y;
    half _1067 = _864.z;
    half _1072 = _864.x;
    half3 _1140 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _1062)) + (half4(frame.sh[2]).xyz * _1067)) + (half4(frame.sh[3]).xyz * _1072)) + (((((half4(frame.sh[4]).xyz * (_1072 * _1062)) + (half4(frame.sh[5]).xyz * (_1062 * _1067))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _1067, _1067, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_1072 * _1067))) + (half4(frame.sh[8]).xyz * fma(_1072, _1072, half(-float(_1062 * _1062))))), half3(float3(0.0)));
    half3 _1163 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_1013))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1238 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _1013)), half(0.0), half(1.0));
    half3 _1246 = half3((half(0.1599999964237213134765625) * _1238) * _1238);
    half _1255 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _1013)), half(0.08900000154972076416015625), half(1.0));
    half _1198 = max(dot(_864, half3(_870)), half(9.9999997473787516355514526367188e-05));
    float4 _1262 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1198, _1255)), level(0.0));
    half3 _1281 = half3(float3(1.0)) + (_1246 * ((half(1.0) / half4(_1262).y) - half(1.0)));
    float4 _1291 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_870), _864)), level(_1255 * (half(4.0) * (half(2.0) - _1255))));
    half _1430 = _1255 * _1255;
    float3 _1442 = fast::normalize(_870 + frame.lightDirection.xyz);
    half _1351 = clamp(dot(_864, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half _1482 = half(4096.0) * _1430;
    half4 _1507 = half4(cross(_864, half3(_1442)), _1430 * clamp(dot(_864, half3(_1442)), half(0.0), half(1.0))) * half(64.0);
    half _1488 = _1482 / dot(_1507, _1507);
    half _1518 = _1430 * _1430;
    half _1524 = fma(half(-float(_1430)), _1430, half(1.0));
    half _1528 = sqrt(fma(_1198 * _1198, _1524, _1518));
    half _1552 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1442)), half(0.0), half(1.0));
    half _1555 = _1552 * _1552;
    half3 _1563 = half3(float3(1.0)) - _1246;
    half3 _1382 = _1163 * half(0.3183098733425140380859375);
    float3 _1621 = float3(frame.punctualLights[0].positionFalloff.xyz) - in.v_worldPosition;
    float _1624 = dot(_1621, _1621);
    float3 _1629 = _1621 * rsqrt(fast::max(_1624, 9.9999999392252902907785028219223e-09));
    float _1633 = _1624 * float(frame.punctualLights[0].positionFalloff.w);
    float _1638 = fast::clamp(fma(-_1633, _1633, 1.0), 0.0, 1.0);
    float _1657 = fast::clamp(fma(dot(-_1629, float3(frame.punctualLights[0].direction.xyz)), float(frame.punctualLights[0].spotScaleOffset.x), float(frame.punctualLights[0].spotScaleOffset.y)), 0.0, 1.0);
    float3 _1811 = fast::normalize(_870 + _1629);
    half _1720 = clamp(dot(_864, half3(_1629)), half(0.0), half(1.0));
    half4 _1876 = half4(cross(_864, half3(_1811)), _1430 * clamp(dot(_864, half3(_1811)), half(0.0), half(1.0))) * half(64.0);
    half _1857 = _1482 / dot(_1876, _1876);
    half _1921 = half(1.0) - clamp(dot(half3(_1629), half3(_1811)), half(0.0), half(1.0));
    half _1924 = _1921 * _1921;
    float3 _1990 = float3(frame.punctualLights[1].positionFalloff.xyz) - in.v_worldPosition;
    float _1993 = dot(_1990, _1990);
    float3 _1998 = _1990 * rsqrt(fast::max(_1993, 9.9999999392252902907785028219223e-09));
    float _2002 = _1993 * float(frame.punctualLights[1].positionFalloff.w);
    float _2007 = fast::clamp(fma(-_2002, _2002, 1.0), 0.0, 1.0);
    float _2026 = fast::clamp(fma(dot(-_1998, float3(frame.punctualLights[1].direction.xyz)), float(frame.punctualLights[1].spotScaleOffset.x), float(frame.punctualLights[1].spotScaleOffset.y)), 0.0, 1.0);
    float3 _2180 = fast::normalize(_870 + _1998);
    half _2089 = clamp(dot(_864, half3(_1998)), half(0.0), half(1.0));
    half4 _2245 = half4(cross(_864, half3(_2180)), _1430 * clamp(dot(_864, half3(_2180)), half(0.0), half(1.0))) * half(64.0);
    half _2226 = _1482 / dot(_2245, _2245);
    half _2290 = half(1.0) - clamp(dot(half3(_1998), half3(_2180)), half(0.0), half(1.0));
    half _2293 = _2290 * _2290;
    half3 _2323 = ((fma(_1163, _1140, half4(_1291).xyz * (mix(half4(_1262).xxx, half4(_1262).yyy, _1246) * _1281)) + min(fma((_1246 + (_1563 * ((_1555 * _1555) * _1552))) * min(min((_1488 * _1488) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1351, _1528, _1198 * sqrt(fma(_1351 * _1351, _1524, _1518))), half(65504.0)), half(65504.0)), _1281, _1382) * (half4(frame.lightColor).xyz * _1351), half3(float3(65504.0)))) + min(fma((_1246 + (_1563 * ((_1924 * _1924) * _1921))) * min(min((_1857 * _1857) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1720, _1528, _1198 * sqrt(fma(_1720 * _1720, _1524, _1518))), half(65504.0)), half(65504.0)), _1281, _1382) * (half3(fast::min(float3(frame.punctualLights[0].colorIntensity.xyz) * float((half(float(half(_1638) * half(_1638)) / fast::max(_1624, 9.9999997473787516355514526367188e-05)) * half(_1657)) * half(_1657)), float3(65504.0))) * _1720), half3(float3(65504.0)))) + min(fma((_1246 + (_1563 * ((_2293 * _2293) * _2290))) * min(min((_2226 * _2226) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_2089, _1528, _1198 * sqrt(fma(_2089 * _2089, _1524, _1518))), half(65504.0)), half(65504.0)), _1281, _1382) * (half3(fast::min(float3(frame.punctualLights[1].colorIntensity.xyz) * float((half(float(half(_2007) * half(_2007)) / fast::max(_1993, 9.9999997473787516355514526367188e-05)) * half(_2026)) * half(_2026)), float3(65504.0))) * _2089), half3(float3(65504.0)));
    out.fragColor = float4(half4(_2323, half(1.0)));
    return out;
}

