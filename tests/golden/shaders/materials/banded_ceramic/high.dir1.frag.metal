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
    half3 _763 = normalize(half3(in.v_normal));
    float3 _770 = fast::normalize(frame.cameraPosition.xyz - in.v_worldPosition);
    float _876 = smoothstep(float(-half(params.bandSharpness)), params.bandSharpness, sin((in.v_worldPosition.y * params.bandsPerUnit) * 6.283185482025146484375));
    half _925 = _763.y;
    half _930 = _763.z;
    half _935 = _763.x;
    half3 _1003 = max((((half4(frame.sh[0]).xyz + (half4(frame.sh[1]).xyz * _925)) + (half4(frame.sh[2]).xyz * _930)) + (half4(frame.sh[3]).xyz * _935)) + (((((half4(frame.sh[4]).xyz * (_935 * _925)) + (half4(frame.sh[5]).xyz * (_925 * _930))) + (half4(frame.sh[6]).xyz * fma(half(3.0) * _930, _930, half(-1.0)))) + (half4(frame.sh[7]).xyz * (_935 * _930))) + (half4(frame.sh[8]).xyz * fma(_935, _935, half(-float(_925 * _925))))), half3(float3(0.0)));
    half3 _1026 = clamp(half3(mix(float3(params.clayColor), params.glazeColor, float3(_876))), half3(float3(0.0)), half3(float3(1.0))) * half(1.0);
    half _1101 = clamp(half(mix(0.3499999940395355224609375, 0.60000002384185791015625, _876)), half(0.0), half(1.0));
    half3 _1109 = half3((half(0.1599999964237213134765625) * _1101) * _1101);
    half _1118 = clamp(half(mix(params.clayRoughness, params.glazeRoughness, _876)), half(0.08900000154972076416015625), half(1.0));
    half _1061 = max(dot(_763, half3(_770)), half(9.9999997473787516355514526367188e-05));
    float4 _1125 = facet_dfgLut.sample(facet_dfgLutSmplr, float2(half2(_1061, _1118)), level(0.0));
    half3 _1144 = half3(float3(1.0)) + (_1109 * ((half(1.0) / half4(_1125).y) - half(1.0)));
    float4 _1151 = facet_environment.sample(facet_environmentSmplr, float3(reflect(-half3(_770), _763)), level(_1118 * half(4.0)));
    half _1290 = _1118 * _1118;
    float3 _1302 = fast::normalize(_770 + frame.lightDirection.xyz);
    half _1211 = clamp(dot(_763, half3(frame.lightDirection.xyz)), half(0.0), half(1.0));
    half3 _1363 = cross(_763, half3(_1302)) * half(64.0);
    half _1367 = clamp(dot(_763, half3(_1302)), half(0.0), half(1.0)) * (half(64.0) * _1290);
    half _1349 = (half(4096.0) * _1290) / fma(_1367, _1367, dot(_1363, _1363));
    half _1382 = _1290 * _1290;
    half _1388 = fma(half(-float(_1290)), _1290, half(1.0));
    half _1416 = half(1.0) - clamp(dot(half3(frame.lightDirection.xyz), half3(_1302)), half(0.0), half(1.0));
    half _1419 = _1416 * _1416;
    half3 _1449 = fma(_1026, _1003, half4(_1151).xyz * (mix(half4(_1125).xxx, half4(_1125).yyy, _1109) * _1144)) + min(fma((_1109 + ((half3(float3(1.0)) - _1109) * ((_1419 * _1419) * _1416))) * min(min((_1349 * _1349) * half(0.3183098733425140380859375), half(65504.0)) * min(half(0.5) / fma(_1211, sqrt(fma(_1061 * _1061, _1388, _1382)), _1061 * sqrt(fma(_1211 * _1211, _1388, _1382))), half(65504.0)), half(65504.0)), _1144, _1026 * half(0.3183098733425140380859375)) * (half4(frame.lightColor).xyz * _1211), half3(float3(65504.0)));
    out.fragColor = float4(half4(_1449, half(1.0)));
    return out;
}

